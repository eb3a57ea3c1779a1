#include "nineball/carom_rack.hpp"

namespace nineball::rules {

int innings(const Rack& rack, Player p) {
  return rack.state().innings[p == Player::A ? 0 : 1];
}

int highRun(const Rack& rack, Player p) {
  return rack.state().high_run[p == Player::A ? 0 : 1];
}

void replayOpening(Rack& rack) {
  RackState s = rack.state();
  s.break_next = true;
  rack.setState(s);
}

}  // namespace nineball::rules
