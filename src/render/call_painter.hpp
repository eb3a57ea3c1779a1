#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <optional>

#include "nineball/vec2.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// A called shot on the table: a ring round the called ball, a marker in the called pocket
/// (either may be missing while the call is being made).
struct CallMark {
  std::optional<Vec2> ball;    ///< the called ball's centre, m
  std::optional<Vec2> pocket;  ///< the called pocket's drop centre, m
};

/// The colour of the call's ring and marker.
constexpr unsigned char kCallRgb[3] = {255, 196, 0};

/// Draws the call over the balls.
void drawCall(sf::RenderTarget& target, const ViewTransform& view, const CallMark& call,
              double ball_radius);

}  // namespace nineball::render
