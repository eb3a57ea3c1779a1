#include "window/seats/seats.hpp"

#include "common/overloaded.hpp"

namespace nineball::window {

void Seats::setRemote(int seat, const RemoteControl& remote) {
  remote_ = Remote{seat, &remote};
}

WindowSeat Seats::seat(int index) const {
  if (remote_ && remote_->seat == index) return RemoteSeat{remote_->control};
  if (index == ComputerPlayer::kSeat && isComputer(computer_.opponent())) {
    return PlannerSeat{&computer_};
  }
  return LocalSeat{};
}

WindowSeat Seats::mover(const GameSession& session) const {
  // A remote player also holds this side's turns while its link is not settled (or a script
  // plays them): it says so itself.
  if (remote_ && remote_->control->controls(session)) return RemoteSeat{remote_->control};
  return seat(session.seatToMove());
}

bool Seats::controls(const GameSession& session) const {
  return std::visit(Overloaded{[](LocalSeat) { return false; },
                               [&](PlannerSeat c) { return c.player->controls(session); },
                               [&](RemoteSeat r) { return r.remote->controls(session); }},
                    mover(session));
}

bool Seats::showsCue(const GameSession& session) const {
  return std::visit(Overloaded{[](LocalSeat) { return false; },
                               [](PlannerSeat c) { return c.player->showsCue(); },
                               [](RemoteSeat r) { return r.remote->showsCue(); }},
                    mover(session));
}

double Seats::pull(const GameSession& session) const {
  return std::visit(
      Overloaded{[](LocalSeat) { return 0.0; }, [](PlannerSeat c) { return c.player->pull(); },
                 [](RemoteSeat r) { return r.remote->pull(); }},
      mover(session));
}

std::string Seats::status(const GameSession& session) const {
  return std::visit(Overloaded{[&](LocalSeat) { return session.status(); },
                               [&](PlannerSeat c) { return c.player->status(session); },
                               [&](RemoteSeat r) { return r.remote->status(session); }},
                    mover(session));
}

}  // namespace nineball::window
