#include "window/online_play.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <type_traits>

#include "common/log.hpp"
#include "common/overloaded.hpp"
#include "net/handshake.hpp"
#include "render/cue_stick_shape.hpp"
#include "window/seat_token_file.hpp"

namespace nineball::window {
namespace {

// How long the joiner waits for the host's answer to its hello.
constexpr double kWelcomeSeconds = 10.0;

AimPose poseOf(const net::Aim& a) {
  return {a.heading_rad, a.speed, a.tip, a.elevation_rad, a.cue};
}

}  // namespace

std::unique_ptr<OnlinePlay> OnlinePlay::start(const OnlineConfig& config, std::string& why) {
  std::unique_ptr<OnlinePlay> play(new OnlinePlay(config));
  OnlineConfig& c = play->config_;
  if (c.side == net::Side::Joiner && c.seat_token.empty() && !c.seat_file.empty()) {
    c.seat_token = loadSeatToken(c.seat_file, net::addressText(c.address));
  }
  net::PeerConfig p;
  p.side = c.side;
  p.address = c.address;
  p.code = c.code;
  p.hello = net::helloFrom(c.name, c.code, c.seat_token);
  p.wait_s = c.wait_s;
  p.rejoin_s = c.rejoin_s;
  p.connect_s = c.connect_s;
  p.retry_s = c.retry_s;
  p.welcome_s = kWelcomeSeconds;
  p.limits = c.limits;
  p.clock = c.clock;
  play->peer_ = net::Peer::start(p, why);
  if (!play->peer_) return nullptr;
  if (c.side == net::Side::Host) {
    c.code = play->peer_->code();
    logger("online")->info("hosting on port {}: the friend joins with {}", c.address.port,
                           play->joinLine());
  }
  return play;
}

OnlinePlay::OnlinePlay(const OnlineConfig& config)
    : config_(config), driver_(config.side, [this](const net::Message& m) { send(m); }) {
  peer_name_ = config_.side == net::Side::Host ? "Player 2" : "Player 1";
}

OnlinePlay::~OnlinePlay() {
  leave("the window closed");
  if (session_) session_->setTurnRelay({});
}

double OnlinePlay::now() const {
  return config_.clock->now();
}

void OnlinePlay::leave(const std::string& reason) {
  if (!peer_) return;  // start() failed: nothing was linked
  peer_->leave(local_finished_ ? std::nullopt : std::optional<net::Bye>(net::Bye{reason, false}),
               reason);
  if (!ended_) {
    ended_ = true;
    why_ = "You left the game.";
  }
  peer_->end(why_);  // whoever comes later hears why
}

void OnlinePlay::send(const net::Message& message) {
  peer_->send(message);
}

// --- the link ---

void OnlinePlay::update(GameSession& session, double seconds) {
  session_ = &session;
  installRelay(session);
  connectionStep(session);
  finishTurns(session);
  // A turn's messages wait while a shot rolls: the next is played once this one has ended.
  while (!inbox_.empty() && stage() != Stage::Over && session.phase() != Phase::Rolling) {
    const net::Message message = std::move(inbox_.front());
    inbox_.pop_front();
    handle(*session_, message);
    finishTurns(*session_);
  }
  if (stage() == Stage::Playing && local_offer_ && peer_offer_ &&
      session_->phase() == Phase::GameOver && driver_.settled()) {
    rematch_now_ = true;
    session_->rematch();
    rematch_now_ = false;
    newRack(*session_);
    session_->say("Rematch: rack " + std::to_string(session_->rackNumber()) + ", " +
                  session_->seatName(session_->seatToMove()) + " breaks.");
  }
  if (stage() == Stage::Playing) {
    playScript(*session_);
    sendAim(*session_);
    if (config_.stall_s > 0.0 && now() - progress_at_ > config_.stall_s && !finished(*session_)) {
      end("Nothing was played for " + clockText(config_.stall_s) + ": the game is stuck.", true);
    }
  }
  showPeerAim(*session_, seconds);
}

// The peer's step: a newcomer is welcomed between shots only (the welcome then holds every
// turn played); its hello and the link's messages wait in the inbox with the others.
void OnlinePlay::connectionStep(const GameSession& session) {
  const bool between_shots = session.phase() != Phase::Rolling;
  for (net::PeerEvent& event : peer_->poll(between_shots)) {
    std::visit(Overloaded{
                   [&](net::PeerJoined& e) { inbox_.push_back(std::move(e.hello)); },
                   [&](net::PeerMessage& e) { inbox_.push_back(std::move(e.message)); },
                   [&](net::PeerBadMessage& e) {
                     protocolError(peer_name_ + " sent a message this game refuses: " + e.why);
                   },
                   [&](net::PeerLost& e) {
                     why_ = e.reason;
                     if (const auto ended = driver_.linkLost(e.reason)) onEnded(*ended);
                   },
                   [&](net::PeerUnreachable& e) { why_ = e.why; },
                   [&](net::PeerTimedOut& e) { timedOut(e.what); },
               },
               event);
  }
}

void OnlinePlay::timedOut(net::PeerTimedOut::What what) {
  using What = net::PeerTimedOut::What;
  switch (what) {
    case What::NoRejoin:
      return end(peer_name_ + " did not come back within " + clockText(config_.rejoin_s) +
                     ": the game is over.",
                 true);
    case What::NobodyCame:
      return end(config_.side == net::Side::Host
                     ? "Nobody joined within " + clockText(config_.wait_s) + "."
                     : "No host answered at " + net::addressText(config_.address) + " within " +
                           clockText(config_.wait_s) + (why_.empty() ? "" : " (" + why_ + ")") +
                           ".",
                 true);
    case What::NoWelcome:
      return end("The host did not answer the hello within " + clockText(kWelcomeSeconds) +
                     " (its game may be over).",
                 true);
  }
}

void OnlinePlay::linkLost(std::string reason) {
  peer_->lose(std::move(reason));
  why_ = peer_->lastProblem();
}

void OnlinePlay::end(const std::string& reason, bool failure) {
  if (ended_) return;
  ended_ = true;
  why_ = net::cleanText(reason, std::string::npos);  // often the peer's words: shown clean
  peer_->end(why_);
  failed_ = failure;
  if (failure) {
    logger("online")->warn("{}", why_);
  } else {
    logger("online")->info("{}", why_);
  }
}

void OnlinePlay::protocolError(const std::string& reason) {
  peer_->drop(reason);
  end(reason + " - the link was closed.", true);
}

// --- the messages ---

// What the peer said, as the lockstep reads it (src/net): the messages themselves are the
// driver's; the window acts on its events.
void OnlinePlay::handle(GameSession& session, const net::Message& message) {
  // What arrived before a link dropped is still the rack's (a host that finished and left).
  net::RackTable* table = started() ? this : nullptr;
  for (const net::LockstepEvent& event : driver_.hear(message, table, peer_->handshaking())) {
    if (stage() == Stage::Over) return;
    onEvent(session, event);
  }
}

void OnlinePlay::onEvent(GameSession& session, const net::LockstepEvent& event) {
  std::visit(
      Overloaded{
          [&](const net::HelloHeard& e) { onHello(session, e.hello); },
          [&](const net::WelcomeHeard& e) { onWelcome(session, e.welcome); },
          [&](const net::RefuseHeard& e) {
            if (e.busy) return linkLost(e.reason);  // tried again
            end("The other side refused: " + e.reason, true);
          },
          [&](const net::TurnReceived& e) { onTurn(session, e); },
          [&](const net::TurnAgreed&) { progress_at_ = now(); },
          [&](const net::HealStarted& e) { onHealStarted(session, e.index); },
          [&](const net::Healed& e) {
            progress_at_ = now();
            logger("online")->warn("healed: the table was set to the host's after turn {}",
                                   e.index);
            session.say("The two tables differed: this one was set to " + peer_name_ + "'s.",
                        render::Tone::Warning);
          },
          [&](const net::AimHeard& e) {
            if (!ourMove(session) && driver_.settled()) peer_aim_.heard(poseOf(e.aim));
          },
          [&](const net::RematchHeard&) { onRematch(session); },
          [&](const net::ByeHeard& e) { onBye(e); },
          [&](const net::PeerBroke& e) {
            protocolError(peer_name_ + " sent " +
                          (e.out_of_place ? e.why : e.what + " this game refuses: " + e.why));
          },
          [&](const net::LockstepEnded& e) { onEnded(e); },
      },
      event);
}

void OnlinePlay::onHealStarted(GameSession& session, std::size_t index) {
  progress_at_ = now();
  if (config_.side != net::Side::Host) return;  // the host's state is on its way
  session.say("The two tables differed after turn " + std::to_string(index) + ": " + peer_name_ +
                  "'s was set to this one.",
              render::Tone::Warning);
}

void OnlinePlay::onEnded(const net::LockstepEnded& e) {
  using Why = net::LockstepEnded::Why;
  const std::string after = " after turn " + std::to_string(e.index);
  switch (e.why) {
    case Why::Unhealed:
      return end(config_.side == net::Side::Host
                     ? "Out of step with " + peer_name_ + after +
                           ": the tables still differ after the heal."
                     : "Out of step with " + peer_name_ + ": the host's state does not take here.",
                 true);
    case Why::HealsSpent:
      return end("Out of step with " + peer_name_ + after + ": healed " + std::to_string(e.count) +
                     " times in this rack already.",
                 true);
    case Why::RejoinsSpent:
      return end(peer_name_ + " lost the link more than " + std::to_string(e.count) +
                     " times in this rack: the game is over.",
                 true);
  }
}

// "Finished" is believed where the peer's rack can end (the lockstep judged it); anywhere
// else it is a quit.
void OnlinePlay::onBye(const net::ByeHeard& bye) {
  if (bye.finished) {
    peer_finished_ = true;
    return end(peer_name_ + " has played out the rack.", false);
  }
  end(peer_name_ + " left the game (" + bye.reason + ").", false);
}

void OnlinePlay::onHello(GameSession& session, const net::Hello& hello) {
  progress_at_ = now();
  if (const auto refusal = net::refusalOf(hello)) {
    logger("online")->warn("refused {}: {}", hello.name, *refusal);
    peer_->refuseNewcomer(*refusal);
    why_ = "Refused a player: " + *refusal;
    session.say(why_, render::Tone::Warning);
    return;
  }
  peer_name_ = hello.name.empty() ? std::string("Player 2") : net::cleanName(hello.name);
  // Two players of one name are told apart by their seats.
  if (peer_name_ == config_.name) peer_name_ = net::cleanName(peer_name_ + " (B)");
  session.setSeatName(1, peer_name_);
  session.setSeatName(0, config_.name);
  if (started()) {
    // Back on a new link while the old one looked alive: that link counts as lost.
    if (const auto ended = driver_.rejoinHeard()) {
      peer_->refuseNewcomer("the game is over: " + peer_name_ + " lost the link too often");
      return onEnded(*ended);
    }
  } else {
    session.setFixedSeats(true);
    if (session.bestOf() == 0) session.setBestOf(1);  // the race needs a length: one rack
    newRack(session);
  }
  peer_->handshakeDone();
  driver_.welcome(hello, session.rackSetup(), config_.name, config_.match, race(session),
                  peer_->seatToken());
  if (!driver_.lockstep()->turns().empty()) {
    session.say(peer_name_ + " is back: the rack goes on.");
  } else {
    session.say(peer_name_ + " joined. " + session.seatName(session.seatToMove()) + " breaks.");
  }
  logger("online")->info("{} joined ({} turns so far)", peer_name_,
                         driver_.lockstep()->turns().size());
}

void OnlinePlay::onWelcome(GameSession& session, const net::Welcome& welcome) {
  progress_at_ = now();
  if (const auto refusal = net::refusalOf(welcome)) {
    peer_->drop(*refusal);
    end("Cannot play this host: " + *refusal, true);
    return;
  }
  std::string why;
  const std::optional<MatchSetup> setup = net::setupOf(welcome, why);
  if (!setup) return protocolError("The host's match is refused: " + why);
  peer_name_ = welcome.name.empty() ? std::string("Player 1") : net::cleanName(welcome.name);
  if (peer_name_ == config_.name) peer_name_ = net::cleanName(peer_name_ + " (A)");
  if (welcome.token != config_.seat_token && !config_.seat_file.empty()) {
    keepSeatToken(config_.seat_file, net::addressText(config_.address), welcome.token);
  }
  config_.seat_token = welcome.token;
  peer_->setSeatToken(welcome.token);
  std::optional<GameSession> made;
  try {
    made.emplace(*setup);
    made->setFixedSeats(true);
    made->setBestOf(welcome.race.best_of);
    made->resumeRack(welcome.race.rack, welcome.race.racks_won[0], welcome.race.racks_won[1]);
  } catch (const std::exception& e) {
    return protocolError(std::string("The host's match cannot be set up here: ") + e.what());
  }
  GameSession& fresh = *made;
  fresh.setSeatName(0, peer_name_);
  fresh.setSeatName(1, config_.name);
  // The rack so far, replayed as a saved rack is (window/rack_save.cpp replayRack): the same
  // build plays the same turns to the same position.
  const rules::Player own = net::seatOf(config_.side);
  std::vector<std::uint64_t> hashes;
  std::size_t own_turns = 0;
  for (std::size_t i = 0; i < welcome.turns.size(); ++i) {
    const auto input = net::parseWireTurn(welcome.turns[i], fresh.rackSetup(), why);
    if (!input)
      return protocolError("The host's turn " + std::to_string(i) + " is refused: " + why);
    // A turn after the rack ended (won, or a shot that left balls moving) is no rack's.
    if (fresh.match().rack().over() || !fresh.match().world().atRest()) {
      return protocolError("The host's turn " + std::to_string(i) +
                           " comes after the rack was over");
    }
    if (fresh.match().rack().shooter() == own) ++own_turns;
    try {
      fresh.playTurn(*input);
    } catch (const std::exception& e) {
      return protocolError("The host's turn " + std::to_string(i) +
                           " does not replay: " + e.what());
    }
    hashes.push_back(snapshotHash(fresh.match().snapshot()));
  }
  session = std::move(fresh);
  replaced_ = true;
  installRelay(session);  // this side's next turn may be played in this very frame
  pending_.reset();
  local_offer_ = peer_offer_ = false;
  peer_aim_.reset();
  script_next_ = std::min(own_turns, config_.script.size());
  const bool rejoin = peer_->stage() == Stage::Lost;
  peer_->handshakeDone();
  driver_.welcomed(session.rackSetup(), welcome.turns, hashes);
  session.say(rejoin ? "Back with " + peer_name_ + ": the rack goes on."
                     : "Playing " + peer_name_ + " online. " +
                           session.seatName(session.seatToMove()) + " breaks.");
  logger("online")->info("{} {}: {} turns replayed", rejoin ? "rejoined" : "joined", peer_name_,
                         welcome.turns.size());
}

void OnlinePlay::onTurn(GameSession& session, const net::TurnReceived& received) {
  const net::CheckedTurn& turn = received.turn;
  playing_peer_turn_ = true;
  const std::size_t before = session.rackTurns().size();
  try {
    if (turn.input.kind == TurnInput::Kind::Decision) {
      session.decide(turn.input.shoot, turn.input.replace);
    } else {
      session.shoot(turn.input);
    }
  } catch (const std::exception& e) {
    // The rules refused it here (the turn was checked, so the tables differ): never a crash.
    session.say(e.what(), render::Tone::Warning);
  }
  playing_peer_turn_ = false;
  if (session.rackTurns().size() == before) {
    end(peer_name_ + "'s turn " + std::to_string(received.message.index) +
            " could not be played here (" + session.message() + "): out of step.",
        true);
    return;
  }
  pending_ = received.message.turn;
  peer_aim_.reset();
  peer_aiming_ = false;
}

void OnlinePlay::onRematch(GameSession& session) {
  peer_offer_ = true;
  if (!local_offer_) session.say(peer_name_ + " offers a rematch: R accepts.");
}

// --- the turns ---

void OnlinePlay::installRelay(GameSession& session) {
  if (session.hasTurnRelay()) return;
  GameSession::TurnRelay relay;
  relay.prepare = [this](const TurnInput& turn) -> std::optional<TurnInput> {
    if (playing_peer_turn_) return turn;
    if (!session_ || !ourMove(*session_)) return std::nullopt;
    net::TurnMessage message;
    const net::CheckedTurn checked = driver_.localTurn(turn, HumanSeat{}, message);
    outgoing_ = message;
    return checked.input;
  };
  relay.begun = [this](const TurnInput&) {
    if (playing_peer_turn_ || !outgoing_) return;
    send(*outgoing_);
    pending_ = outgoing_->turn;
    outgoing_.reset();
    throttle_.reset();
  };
  relay.rematch = [this]() {
    if (rematch_now_) return true;
    if (stage() != Stage::Playing || !session_) return false;
    if (!local_offer_) {
      local_offer_ = true;
      send(net::Rematch{});
      session_->say(peer_offer_ ? "Rematch accepted."
                                : "Rematch offered: waiting for " + peer_name_ + " to accept.");
    }
    return false;
  };
  session.setTurnRelay(std::move(relay));
}

void OnlinePlay::newRack(GameSession& session) {
  driver_.newRack(session.rackSetup());
  pending_.reset();
  outgoing_.reset();
  local_offer_ = peer_offer_ = false;
  local_finished_ = peer_finished_ = false;
  // A script's turns are played once: a rematch goes on from the next (none: it ends there).
  peer_aim_.reset();
  peer_aiming_ = false;
}

void OnlinePlay::finishTurns(GameSession& session) {
  if (!pending_ || !started() || session.phase() == Phase::Rolling) return;
  if (session.rackTurns().size() <= driver_.lockstep()->turns().size()) return;
  progress_at_ = now();
  driver_.played(*pending_, session.match().snapshot());
  pending_.reset();
}

void OnlinePlay::playScript(GameSession& session) {
  if (!config_.scripted || local_finished_ || pending_ || !ourMove(session)) return;
  const Phase phase = session.phase();
  if (phase != Phase::Aiming && phase != Phase::PushOutChoice) return;
  if (script_next_ >= config_.script.size()) {
    local_finished_ = true;
    send(net::Bye{"this side's script is over", true});
    return;
  }
  const std::size_t index = script_next_++;
  const TurnInput& turn = config_.script[index];
  const std::size_t before = session.rackTurns().size();
  try {
    if (turn.kind == TurnInput::Kind::Decision) {
      if (phase == Phase::PushOutChoice) session.decide(turn.shoot, turn.replace);
    } else if (phase == Phase::Aiming) {
      session.shoot(turn);
    }
  } catch (const std::exception& e) {
    session.say(e.what(), render::Tone::Warning);
  }
  if (session.rackTurns().size() == before) {
    const bool decision = turn.kind == TurnInput::Kind::Decision;
    const std::string why = decision != (phase == Phase::PushOutChoice)
                                ? (decision ? "a shot is due, not a decision"
                                            : "a decision is due (play on or pass), not a shot")
                                : session.message();
    end("The script's turn " + std::to_string(index) + " was refused" +
            (why.empty() ? std::string(".") : ": " + why),
        true);
    leave("this side's script turn was refused");
  }
}

// --- the aim ---

void OnlinePlay::sendAim(const GameSession& session) {
  if (config_.scripted || !ourMove(session) || session.phase() != Phase::Aiming) return;
  AimPose pose{session.heading(), session.speed(), session.tip(), session.elevation(),
               std::nullopt};
  if (session.cueInHand()) pose.cue = session.cuePosition();
  if (!throttle_.due(pose, now())) return;
  net::Aim aim;
  aim.heading_rad = pose.heading_rad;
  aim.speed = pose.speed;
  aim.tip = pose.tip;
  aim.elevation_rad = pose.elevation_rad;
  aim.cue = pose.cue;
  send(aim);
}

void OnlinePlay::showPeerAim(GameSession& session, double seconds) {
  peer_aiming_ = false;
  if (stage() != Stage::Playing || ourMove(session) || !driver_.settled() ||
      session.phase() != Phase::Aiming) {
    return;
  }
  const std::optional<AimPose> pose = peer_aim_.advance(seconds);
  if (!pose) return;
  peer_aiming_ = true;
  session.setHeading(pose->heading_rad);
  session.setSpeed(pose->speed);
  session.setTip(pose->tip);
  session.setElevation(pose->elevation_rad);
  if (pose->cue && session.cueInHand() && !session.placementProblem(*pose->cue)) {
    session.placeCue(*pose->cue);
  }
  peer_power_ = session.power();
}

bool OnlinePlay::ourMove(const GameSession& session) const {
  return stage() == Stage::Playing && !pending_ && !outgoing_ &&
         driver_.localToMove(session.match());
}

net::Race OnlinePlay::race(const GameSession& session) const {
  net::Race r;
  r.best_of = std::clamp(session.bestOf(), 1, 99);
  r.rack = std::clamp(session.rackNumber() - 1, 0, 200);
  r.racks_won = {std::clamp(session.racksWon(0), 0, 99), std::clamp(session.racksWon(1), 0, 99)};
  return r;
}

}  // namespace nineball::window
