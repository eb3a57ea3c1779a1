#pragma once

namespace nineball::physics {

/// What an engine's event search has done since it was made: each prediction is worked out
/// once and kept until one of its balls changes, so these grow with the balls each event
/// touches, not with the balls on the table.
struct SearchWork {
  long events = 0;            ///< events found (phase ends and sensor reports included)
  long ball_predictions = 0;  ///< a ball's own next event (phase end, cushion, pocket) worked out
  long pair_predictions = 0;  ///< a pair's next contact worked out past the bounding-box test
};

}  // namespace nineball::physics
