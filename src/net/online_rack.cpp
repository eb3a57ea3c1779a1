#include "net/online_rack.hpp"

#include <chrono>
#include <deque>
#include <future>
#include <memory>
#include <optional>
#include <thread>

#include "common/log.hpp"
#include "io/snapshot_json.hpp"
#include "net/handshake.hpp"
#include "net/lockstep_driver.hpp"
#include "net/peer.hpp"
#include "nineball/planner.hpp"

namespace nineball::net {
namespace {

using Outcome = OnlineRackResult::Outcome;

// However the players play, a rack stops after this many turns (as `nineball match`).
constexpr std::size_t kMaxTurns = kMostTurns;
// How long the joiner waits for the welcome (no longer than its wait or rejoin time allows).
constexpr double kHandshakeSeconds = 5.0;
// Between two attempts to reach the host again.
constexpr double kRetrySeconds = 0.25;

void rackNap() {
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

// Each computer player draws its cueing errors from its own stream, fixed by the match's seed
// (the same streams as `nineball match`, so a rack of two computers plays as it does there).
std::uint64_t plannerSeed(std::uint64_t seed, rules::Player p) {
  return seed * 0x9E3779B97F4A7C15ull + (p == rules::Player::A ? 1u : 2u);
}

// The headless driver of a Peer and the rack's LockstepDriver: a loop that polls the peer,
// acts on what it reported, plays this side's turn (the script's or the computer's), naps and
// hears `quit`. The peer owns the link, the gate, the handshake's timing and the rejoin
// window; the lockstep driver what the peer's messages mean; this driver the table.
class OnlineRack final : private RackTable {
 public:
  explicit OnlineRack(const OnlineRackOptions& o)
      : o_(o),
        token_(o.seat_token),
        driver_(
            o.side, [this](const Message& m) { send(m); }, o.most_heals, o.most_rejoins) {
    if (o_.on_heal) driver_.setOnHeal(o_.on_heal);
  }

  OnlineRackResult run() {
    if (startPeer()) {
      while (!over_) loopOnce();
    }
    if (match_) describeRack();
    // What the peer said reaches the terminal: without control characters.
    result_.why = cleanText(result_.why, std::string::npos);
    if (peer_ && peer_->linked()) {
      peer_->flush(1.0);
      // The side that closes first holds its port for a minute (TCP's TIME_WAIT), and SFML's
      // listener cannot reuse a held port: the host lets the joiner close first, so it can
      // host again at once.
      if (o_.side == Side::Host) peer_->awaitClose(1.0);
    }
    if (peer_) peer_->leave(std::nullopt, "done");
    return result_;
  }

 private:
  // RackTable
  const Match& match() const override { return *match_; }
  void restore(const MatchSnapshot& state) override { match_->restore(state); }

  double seconds() const { return o_.clock->now(); }
  void send(const Message& m) { peer_->send(m); }
  bool inRack() const { return match_ && !awaiting_; }

  // One step: quit, the peer's events, this side's move (or the peer's turn limit), a nap
  // when nothing happened.
  void loopOnce() {
    if (o_.quit && o_.quit->load()) return quit();
    poll();
    bool acted = !events_.empty();
    while (!over_ && !events_.empty()) {
      PeerEvent e = std::move(events_.front());
      events_.pop_front();
      onEvent(e);
    }
    if (!over_ && inRack()) acted = step() || acted;
    if (!over_ && !acted) rackNap();
  }

  void poll() {
    for (PeerEvent& e : peer_->poll()) events_.push_back(std::move(e));
  }

  // The rack ends here (the result says why).
  void end(Outcome outcome, const std::string& why) {
    result_.outcome = outcome;
    result_.why = why;
    logger("net")->info("rack ends: {}", why);
    over_ = true;
  }

  // Said to the peer before an end: it reaches the other side before the link closes.
  void sayBye(const std::string& reason, bool finished) {
    send(Bye{reason, finished});
    peer_->flush(0.5);
  }

  // Ctrl-C: the other side hears that this one left, and the rack ends here.
  void quit() {
    if (peer_->linked()) sayBye("the other player quit", false);
    end(Outcome::Quit, "quit before the rack was over");
  }

  // --- the peer ---

  bool startPeer() {
    PeerConfig c;
    c.side = o_.side;
    c.address = o_.address;
    c.code = o_.code;
    c.hello = helloFrom(o_.name, o_.code, token_, localPlayer());
    c.wait_s = o_.wait_s;
    c.rejoin_s = o_.rejoin_s;
    c.connect_s = o_.connect_s;
    c.retry_s = kRetrySeconds;
    c.welcome_s = kHandshakeSeconds;
    c.welcome_within_wait = true;
    c.limits = o_.limits;
    c.gate = o_.gate;
    c.clock = o_.clock;
    std::string why;
    peer_ = Peer::start(c, why);
    if (!peer_) {
      result_.outcome = Outcome::NoPeer;
      result_.why = why;
      return false;
    }
    if (o_.side == Side::Host) {
      logger("net")->info("hosting on port {}: join with --join {}:{} --code {}", o_.address.port,
                          localAddress(), o_.address.port, peer_->code());
    }
    return true;
  }

  void onEvent(PeerEvent& e) {
    if (auto* joined = std::get_if<PeerJoined>(&e)) return onJoined(joined->hello);
    if (const auto* t = std::get_if<PeerTimedOut>(&e)) return onTimedOut(t->what);
    if (inRack()) return onRackEvent(e);
    if (o_.side == Side::Joiner) onJoinEvent(e);
  }

  void onRackEvent(PeerEvent& e) {
    if (const auto* lost = std::get_if<PeerLost>(&e)) return onLinkLost(lost->reason);
    if (const auto* bad = std::get_if<PeerBadMessage>(&e)) {
      return refusePeer("a bad message (" + bad->why + ")");
    }
    if (auto* in = std::get_if<PeerMessage>(&e)) {
      for (LockstepEvent& l : driver_.hear(in->message, this, peer_->handshaking())) {
        if (!over_ && !awaiting_) onLockstep(l);
      }
    }
  }

  // What the lockstep made of the peer's message.
  void onLockstep(LockstepEvent& e) {
    if (auto* turn = std::get_if<TurnReceived>(&e)) return playPeerTurn(*turn);
    if (const auto* bye = std::get_if<ByeHeard>(&e)) {
      if (bye->finished)
        return end(Outcome::InStep, "the other side's rack is played: " + bye->reason);
      return end(Outcome::LinkLost, "the other player left: " + bye->reason);
    }
    if (const auto* r = std::get_if<RefuseHeard>(&e)) {
      return end(Outcome::Refused, "the other side refused: " + r->reason);
    }
    if (const auto* broke = std::get_if<PeerBroke>(&e)) return refusePeer(broke->why);
    if (const auto* ended = std::get_if<LockstepEnded>(&e)) {
      peer_->flush(0.5);
      return end(Outcome::OutOfStep, ended->reason);
    }
    // Agreements, heals under way, aims and rematch offers change nothing here.
  }

  // The other side broke the protocol: tell it why and drop it; it may rejoin. (When the
  // peer already took a new link from the same player, the old one is gone unheard.)
  void refusePeer(const std::string& why) {
    logger("net")->warn("the other side sent {}: disconnected it", cleanText(why, 400));
    forgetOldLink();
    if (rejoinQueued()) return;
    send(Refuse{"disconnected: you sent " + why});
    peer_->flush(0.5);
    const std::string reason = "it sent " + why;
    peer_->lose(reason);
    onLinkLost(reason);
  }

  // What the dropped link said after what was being played: not the rack's any more.
  void forgetOldLink() {
    while (!events_.empty() && !std::holds_alternative<PeerJoined>(events_.front())) {
      events_.pop_front();
    }
  }

  bool rejoinQueued() const {
    return !events_.empty() && std::holds_alternative<PeerJoined>(events_.front());
  }

  // A lost link: the rack pauses, and goes on if the peer comes back in time.
  void onLinkLost(const std::string& reason) {
    lost_ = reason;
    turn_deadline_ = 0.0;
    if (const auto ended = driver_.linkLost(reason)) return end(Outcome::LinkLost, ended->reason);
    logger("net")->warn("link lost ({}): waiting up to {} s for a rejoin", reason, o_.rejoin_s);
    awaiting_ = true;
  }

  // A wait ran out: nobody came (or came back), or the joiner's host never answered.
  void onTimedOut(PeerTimedOut::What what) {
    if (what == PeerTimedOut::What::NoWelcome) {
      join_why_ = "the host did not answer the hello";
      return;
    }
    if (match_) return end(Outcome::LinkLost, "the link was lost (" + lost_ + ") and not rejoined");
    over_ = true;
    if (o_.side == Side::Joiner) {
      // Nobody answered, or only "busy" or silence did (a bad welcome has said LinkLost).
      if (result_.outcome == Outcome::InStep) {
        result_.outcome = Outcome::NoPeer;
        result_.why = join_why_;
      }
    } else if (!peer_->buildRefusal().empty()) {
      // The host's friend knew the code but runs another build: say so, not "nobody".
      result_.outcome = Outcome::Refused;
      result_.why = "refused the other side: " + peer_->buildRefusal();
    } else {
      result_.outcome = Outcome::NoPeer;
      result_.why = "nobody joined within " + std::to_string(static_cast<int>(o_.wait_s)) + " s";
    }
  }

  // --- the handshake ---

  // The host: a newcomer the gate let in is welcomed to the match (the rack as it stands,
  // when it is a rejoin; its new link replacing the old one counts as that link lost).
  void onJoined(const Hello& hello) {
    const bool rejoin = match_ != nullptr;
    if (inRack()) {
      lost_ = "the other player connected again";
      if (const auto ended = driver_.rejoinHeard()) return end(Outcome::LinkLost, ended->reason);
    }
    peer_name_ = hello.name;
    if (!match_) startRack(o_.script.setup);
    peer_->handshakeDone();
    driver_.welcome(hello, o_.script.setup, o_.name, o_.match, Race{}, peer_->seatToken());
    awaiting_ = false;
    turn_deadline_ = 0.0;
    logger("net")->info("{} joined", peer_name_);
    if (rejoin) logger("net")->info("rejoined after turn {}", driver_.lockstep()->turns().size());
  }

  // The joiner reaching the host (again and again until its wait, or the rejoin window, runs
  // out): the first answer is a welcome, whose rack is replayed, or a refusal.
  void onJoinEvent(PeerEvent& e) {
    if (const auto* u = std::get_if<PeerUnreachable>(&e)) {
      join_why_ = u->why;
    } else if (const auto* lost = std::get_if<PeerLost>(&e)) {
      join_why_ = "the host closed the link (" + lost->reason + ")";
    } else if (const auto* bad = std::get_if<PeerBadMessage>(&e)) {
      send(Refuse{"a bad first message (" + bad->why + ")"});
      peer_->flush(0.5);
      peer_->lose("it sent a bad first message", true);
    } else if (auto* in = std::get_if<PeerMessage>(&e)) {
      onFirstAnswer(in->message);
    }
  }

  // A join that cannot go on: before the rack as the result says, during it as a lost link.
  void joinFailed() {
    if (match_) return end(Outcome::LinkLost, "the link was lost (" + lost_ + ") and not rejoined");
    over_ = true;
  }

  // The host's first answer: a welcome (its rack replayed here) or a refusal. Anything else
  // refuses the link, and the peer tries again.
  void onFirstAnswer(const Message& m) {
    if (const auto* r = std::get_if<Refuse>(&m)) {
      result_.why = "the host refused: " + r->reason;
      join_why_ = result_.why;
      peer_->lose(r->reason, true);
      // A full host is tried again; any other refusal is final.
      if (!isBusyRefusal(r->reason)) {
        result_.outcome = Outcome::Refused;
        joinFailed();
      }
      return;
    }
    const auto* w = std::get_if<Welcome>(&m);
    std::string why;
    if (!w) why = "a first message that is not a welcome";
    if (w) {
      if (const auto r = refusalOf(*w)) {
        send(Refuse{*r});
        peer_->flush(0.5);
        result_.outcome = Outcome::Refused;
        result_.why = "refused the host: " + *r;
        return joinFailed();
      }
    }
    const auto setup = w ? setupOf(*w, why) : std::nullopt;
    std::vector<std::uint64_t> hashes;
    const bool replayed = setup && replay(*setup, *w, hashes, why);
    if (over_) return;  // Ctrl-C during the replay
    if (!replayed) {
      send(Refuse{"a bad welcome (" + why + ")"});
      peer_->flush(0.5);
      peer_->lose("it sent a bad welcome", true);
      result_.outcome = Outcome::LinkLost;
      result_.why = "the host sent a bad welcome (" + why + ")";
      join_why_ = result_.why;
      return;
    }
    const bool rejoin = driver_.begun();
    peer_name_ = w->name;
    token_ = w->token;
    peer_->setSeatToken(token_);
    if (o_.on_seat_token) o_.on_seat_token(token_);
    peer_->handshakeDone();
    driver_.welcomed(*setup, w->turns, hashes);
    awaiting_ = false;
    turn_deadline_ = 0.0;
    if (rejoin) logger("net")->info("rejoined after turn {}", w->turns.size());
  }

  Seat localPlayer() const { return o_.script.players[o_.side == Side::Host ? 0 : 1]; }

  // The joiner: the rack from its start, the welcome's turns played again. Between turns the
  // link is kept alive and Ctrl-C heard (false with `why` empty: quit); a turn after one that
  // left balls moving (the rack was over there) refuses the welcome (false, `why`).
  bool replay(const MatchSetup& setup, const Welcome& w, std::vector<std::uint64_t>& hashes,
              std::string& why) {
    startRack(setup);
    for (std::size_t i = 0; i < w.turns.size(); ++i) {
      if (o_.quit && o_.quit->load()) {
        quit();
        return false;
      }
      keepAlive();
      if (rackDone()) {
        why = "turns[" + std::to_string(i) + "] comes after the rack was over";
        return false;
      }
      const auto input = parseWireTurn(w.turns[i], setup, why);
      if (!input) return false;
      try {
        play(CheckedTurn{*input, w.turns[i].player});
      } catch (const IllegalAction& e) {
        why = "turns[" + std::to_string(i) + "] does not replay: " + e.what();
        return false;
      }
      hashes.push_back(snapshotHash(match_->snapshot()));
    }
    if (!hashes.empty() && hashes.back() != w.hashes.back()) {
      logger("net")->warn("the replayed rack differs from the host's: it will be healed");
    }
    return true;
  }

  // --- the rack ---

  void startRack(const MatchSetup& setup) {
    match_ = std::make_unique<Match>(setup);
    if (o_.side == Side::Host) driver_.newRack(setup);
    records_.clear();
    computer_.clear();
    next_script_turn_ = 0;
    partial_ = false;
    const rules::Player seat = seatOf(o_.side);
    // A rejoin keeps the computer's stream of cueing errors where it was.
    if (planner_) return;
    if (const auto level = computerLevel(localPlayer())) {
      planner_ = std::make_unique<ai::Planner>(*level, plannerSeed(setup.seed, seat));
    }
  }

  void play(const CheckedTurn& turn) {
    records_.push_back(match_->play(turn.input));
    computer_.emplace_back();
    if (const auto level = computerLevel(turn.player)) {
      computer_.back() = io::ComputerTurn{*level, turn.input};
    } else if (records_.back().shooter == seatOf(o_.side)) {
      ++next_script_turn_;
    }
  }

  bool rackDone() {
    if (match_->rack().over() || records_.size() >= kMaxTurns) return true;
    if (match_->world().exhausted() || !match_->world().atRest()) {
      partial_ = true;
      return true;
    }
    return false;
  }

  // With the last turn agreed: the rack is played, this side moves, or the peer's turn is
  // awaited (no longer than turn_s). True when something was done.
  bool step() {
    if (!driver_.settled()) return false;
    if (rackDone()) {
      send(Bye{"the rack is played", true});
      end(partial_ ? Outcome::Partial : Outcome::InStep, "the rack is played");
      return true;
    }
    if (driver_.localToMove(*match_)) {
      playLocalTurn();
      return true;
    }
    if (turn_deadline_ == 0.0) {
      turn_deadline_ = seconds() + o_.turn_s;
    } else if (seconds() > turn_deadline_) {
      const std::string why = "no turn within " + std::to_string(static_cast<int>(o_.turn_s)) +
                              " s: the rack is given up";
      sayBye(why, false);
      end(Outcome::LinkLost, "the other player played " + why);
    }
    return false;
  }

  // Keeps the link alive (pings out, events in for later) while this side thinks.
  void keepAlive() {
    if (o_.quit && o_.quit->load()) return;  // the plan finishes first; then the rack ends
    poll();
  }

  std::optional<TurnInput> localChoice() {
    if (planner_) {
      // The computer may think for seconds: the other side must not take it for gone.
      auto plan = std::async(std::launch::async, [this] { return planner_->turnFor(*match_); });
      while (plan.wait_for(std::chrono::milliseconds(10)) != std::future_status::ready) {
        keepAlive();
      }
      return plan.get();
    }
    if (next_script_turn_ < o_.script.turns.size()) return o_.script.turns[next_script_turn_];
    return std::nullopt;
  }

  void playLocalTurn() {
    const auto choice = localChoice();
    if (!choice) {
      send(Bye{"no turn left in the script", true});
      return end(Outcome::InStep, "this side's script has no turn left");
    }
    const Seat player = planner_ ? Seat{ComputerSeat{planner_->level()}} : Seat{HumanSeat{}};
    TurnMessage message;
    const CheckedTurn turn = driver_.localTurn(*choice, player, message);
    const std::size_t script_turn = next_script_turn_;
    try {
      play(turn);
    } catch (const IllegalAction& e) {
      const std::string why = planner_ ? std::string("the computer's turn was refused: ") + e.what()
                                       : "turns[" + std::to_string(script_turn) + "]: " + e.what();
      sayBye("my turn was refused", false);
      return end(Outcome::BadTurn, why);
    }
    if (o_.drop_before_turn && o_.drop_before_turn(message.index)) {
      peer_->closeLink("dropped by the test");
    }
    send(message);
    afterTurn(message.turn);
  }

  void afterTurn(const WireTurn& turn) {
    if (o_.after_turn) o_.after_turn(*match_, records_.size() - 1);
    driver_.played(turn, match_->snapshot());
  }

  void playPeerTurn(const TurnReceived& t) {
    turn_deadline_ = 0.0;
    try {
      play(t.turn);
    } catch (const IllegalAction& e) {
      return refusePeer(std::string("a turn the rules refuse (") + e.what() + ")");
    }
    afterTurn(t.message.turn);
  }

  void describeRack() {
    const Lockstep* l = driver_.lockstep();
    result_.heals = driver_.heals();
    result_.doc = io::matchResultToJson(records_, match_->rack(), match_->balls(), computer_);
    result_.doc["partial"] = partial_;
    nlohmann::ordered_json hashes = nlohmann::ordered_json::array();
    if (l) {
      for (std::uint64_t h : l->hashes()) hashes.push_back(hashText(h));
    }
    result_.doc["hashes"] = hashes;
  }

  const OnlineRackOptions& o_;
  OnlineRackResult result_;
  std::unique_ptr<Peer> peer_;    // the link, the gate, the handshake's timing, the rejoin window
  std::deque<PeerEvent> events_;  // what the peer reported, not yet acted on
  std::string lost_;              // why the link was lost (the rejoin's reason)
  std::string join_why_ = "nobody answered";  // the joiner: why no welcome came yet
  std::string token_;                         // the joiner: its seat token
  LockstepDriver driver_;       // the turns, the hashes, the heal and the rack's allowance
  bool awaiting_ = true;        // no rack on the link yet: waiting for a (re)join
  bool over_ = false;           // the rack is over for this side (the result says why)
  double turn_deadline_ = 0.0;  // the peer's turn must have come by then (0: not waiting)
  std::unique_ptr<Match> match_;
  std::unique_ptr<ai::Planner> planner_;
  std::vector<TurnRecord> records_;
  std::vector<std::optional<io::ComputerTurn>> computer_;
  std::size_t next_script_turn_ = 0;
  std::string peer_name_;
  bool partial_ = false;
};

}  // namespace

OnlineRackResult playOnlineRack(const OnlineRackOptions& options) {
  return OnlineRack(options).run();
}

}  // namespace nineball::net
