#pragma once

#include <gtest/gtest.h>

#include <string>

#include "io/scene_json.hpp"

// What the scene tests ask of the parser: a text refused naming a field, or accepted.
namespace nineball::io::testing {

/// Checks that the text is refused with a message starting "<field>: " and holding `reason`.
inline ::testing::AssertionResult refusedAt(const std::string& text, const std::string& field,
                                            const std::string& reason) {
  const SceneResult r = parseScene(text);
  const auto* e = std::get_if<ParseError>(&r);
  if (!e) return ::testing::AssertionFailure() << "accepted: " << text;
  if (e->message.rfind(field + ": ", 0) != 0 || e->message.find(reason) == std::string::npos) {
    return ::testing::AssertionFailure() << "message \"" << e->message << "\" does not name \""
                                         << field << "\" with \"" << reason << "\"";
  }
  return ::testing::AssertionSuccess();
}

/// The scene the text reads as; a failure of the test when it is refused.
inline Scene accepted(const std::string& text) {
  SceneResult r = parseScene(text);
  if (const auto* e = std::get_if<ParseError>(&r)) {
    ADD_FAILURE() << "refused: " << e->message;
    return {};
  }
  return std::get<Scene>(r);
}

}  // namespace nineball::io::testing
