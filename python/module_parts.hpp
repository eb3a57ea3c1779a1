#pragma once

// What the files of `nineball._core` share: a scene read from Python as the command line reads
// it, and the calls each file defines for the module's table of functions.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

#include "nineball/scenes.hpp"

namespace nineball::python {

namespace py = pybind11;

/// A scene given as a dict (or its JSON text), refused with the command line's message (a
/// ValueError, `where` before it).
Scene parse(py::handle scene, const std::string& where);

/// The table of a scene (its "table" and "physics"; no balls needed) as the physics builds it.
py::dict tableGeometry(py::handle scene);
/// The standard rack of `game` on the scene's table, seeded as the game seeds it.
py::list rackOf(const std::string& game_name, std::uint64_t seed, py::handle scene);

}  // namespace nineball::python
