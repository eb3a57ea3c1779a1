#pragma once

#include "nineball/colours.hpp"

// The colours live in nineball/colours.hpp, shared with the headless pictures; the painters
// keep reading them by their render:: names.
namespace nineball::render {

using nineball::ballColour;
using nineball::isStripe;
using nineball::kBackground;
using nineball::kCloth;
using nineball::kCueBallColour;
using nineball::kCushion;
using nineball::kDiamond;
using nineball::kNumberDisc;
using nineball::kNumberDiscRadius;
using nineball::kPocket;
using nineball::kStripeHalfHeight;
using nineball::kWood;
using nineball::Rgb;

}  // namespace nineball::render
