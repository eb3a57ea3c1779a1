#pragma once

// What the files of `nineball._core` share: a scene read from Python as the command line reads
// it, and the calls each file defines for the module's table of functions.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "nineball/scenes.hpp"

namespace nineball::python {

namespace py = pybind11;

/// What an array holds where there is no value (a ball not on the table, no such event).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// A scene given as a dict (or its JSON text), refused with the command line's message (a
/// ValueError, `where` before it).
Scene parse(py::handle scene, const std::string& where);

/// `threads` as given, checked: an int of 0 (one per core) up to the cores there are.
int threadCount(py::handle threads);
/// Runs `work` on a thread of its own with the GIL released, stopping it (the flag it is
/// handed) on Ctrl-C and raising KeyboardInterrupt once it has stopped.
void runInterruptibly(const std::function<void(const std::atomic<bool>*)>& work);
/// Ball places and strokes as arrays in, final states and event counts and times out.
py::dict simulateArrays(
    py::handle base_scene,
    const py::array_t<double, py::array::c_style | py::array::forcecast>& places,
    const py::array_t<double, py::array::c_style | py::array::forcecast>& shots,
    const std::vector<int>& ids, py::handle threads);
/// The event types' names, in the order of the arrays' event columns.
py::list eventTypeNames();
/// Scenes in, the same arrays out.
py::dict batchArrays(py::handle scenes, py::handle threads, std::size_t first_index);
/// Every ball of a traced run at time t, a dict each.
py::list stateAt(py::handle result, double t, py::handle scene);
/// A traced run's balls at each instant of `times`, as arrays.
py::dict stateAtTimes(py::handle result,
                      const py::array_t<double, py::array::c_style | py::array::forcecast>& times,
                      py::handle scene);
/// Adds the game environment's tables (nineball.env) to the module.
void defineEnv(py::module_& m);

/// The table of a scene (its "table" and "physics"; no balls needed) as the physics builds it.
py::dict tableGeometry(py::handle scene);
/// The standard rack of `game` on the scene's table, seeded as the game seeds it.
py::list rackOf(const std::string& game_name, std::uint64_t seed, py::handle scene);

}  // namespace nineball::python
