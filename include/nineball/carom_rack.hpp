#pragma once

#include "nineball/rules.hpp"

/// What only a carom game played to a distance keeps (UMB's three-cushion), read from and
/// applied to the generic Rack.
namespace nineball::rules {

/// `p`'s innings so far, the one being played included.
int innings(const Rack& rack, Player p);
/// `p`'s best inning: the most points he made in one visit.
int highRun(const Rack& rack, Player p);
/// The balls were set up in the opening position again (carom's frozen balls): the next shot
/// is played as the opening one.
void replayOpening(Rack& rack);

}  // namespace nineball::rules
