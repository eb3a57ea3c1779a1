#pragma once

#include <SFML/Graphics/RenderTarget.hpp>
#include <string>

#include "play/aim_guide.hpp"
#include "render/fonts.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// Marks an aim guide whose first ball would be a foul: its path and ghost ball in red. Drawn
/// over the guide, under the balls.
void drawGuideFoulPath(sf::RenderTarget& target, const ViewTransform& view, const AimGuide& guide,
                       double ball_radius);

/// `why` beside the ghost ball of a guide whose first ball would be a foul. Drawn over the
/// balls, so that a rack does not hide the words.
void drawGuideFoulLabel(sf::RenderTarget& target, const ViewTransform& view, const AimGuide& guide,
                        double ball_radius, const std::string& why, const Fonts& fonts);

}  // namespace nineball::render
