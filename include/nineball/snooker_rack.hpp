#pragma once

#include "nineball/rules.hpp"

/// What only snooker's frame has, read from and applied to the generic Rack (WPBSA's rules).
namespace nineball::rules {

/// The points the balls left can still give do not cover `p`'s deficit: he needs snookers.
bool snookersRequired(const Rack& rack, Player p);
/// The coming stroke is a free ball (stateFreeBall): the balls on of a foul's free ball are
/// then in legalFirstBalls().
bool freeBall(const Rack& rack);
/// After a foul the match states whether the incoming striker is snookered (WPBSA 3.12): a
/// free ball. Ignored after a legal stroke or once the frame is over.
void stateFreeBall(Rack& rack, bool snookered);
/// The frame ended level on the black and is decided on the re-spotted black (WPBSA 3.4).
bool respottedBlack(const Rack& rack);
/// After a foul and a miss (Decision::PlayPutBackOrReplace): the balls go back where they were
/// before the stroke (the caller puts them there) and the offender plays it again; the penalty
/// stays scored. Throws std::logic_error when not offered.
void replaceAfterMiss(Rack& rack);

}  // namespace nineball::rules
