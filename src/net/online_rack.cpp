#include "net/online_rack.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <future>
#include <memory>
#include <optional>
#include <thread>

#include "common/log.hpp"
#include "io/snapshot_json.hpp"
#include "net/handshake.hpp"
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

void nap() {
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

// Each computer player draws its cueing errors from its own stream, fixed by the match's seed
// (the same streams as `nineball match`, so a rack of two computers plays as it does there).
std::uint64_t plannerSeed(std::uint64_t seed, rules::Player p) {
  return seed * 0x9E3779B97F4A7C15ull + (p == rules::Player::A ? 1u : 2u);
}

// The rack is over for this side (the result says why).
struct Stop {};
// The link closed, or the peer broke the protocol and was dropped: the rack waits for a rejoin.
struct Dropped {};

// The headless driver of a Peer: a loop that polls the peer, plays this side's turns (the
// script's or the computer's) and the peer's, waits a little, and hears `quit`. The peer owns
// the link, the gate, the handshake's timing and the rejoin window; the rack owns the table.
class OnlineRack {
 public:
  explicit OnlineRack(const OnlineRackOptions& o)
      : o_(o), token_(o.seat_token), allowance_(o.most_heals, o.most_rejoins) {}

  OnlineRackResult run() {
    try {
      if (startPeer() && (o_.side == Side::Host ? awaitJoiner() : join())) playRack();
    } catch (const Stop&) {
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
  double seconds() const { return o_.clock->now(); }

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

  // The peer's next event: polled (napping between polls) until there is one.
  PeerEvent nextEvent() {
    while (events_.empty()) {
      leaveIfAsked();
      poll();
      if (events_.empty()) nap();
    }
    PeerEvent e = std::move(events_.front());
    events_.pop_front();
    return e;
  }

  void poll() {
    for (PeerEvent& e : peer_->poll()) events_.push_back(std::move(e));
  }

  [[noreturn]] void end(Outcome outcome, const std::string& why) {
    result_.outcome = outcome;
    result_.why = why;
    logger("net")->info("rack ends: {}", why);
    throw Stop{};
  }

  void send(const Message& m) { peer_->send(m); }

  // Ctrl-C: the other side hears that this one left, and the rack ends here.
  void leaveIfAsked() {
    if (!o_.quit || !o_.quit->load()) return;
    if (peer_->linked()) {
      send(Bye{"the other player quit", false});
      peer_->flush(0.5);
    }
    end(Outcome::Quit, "quit before the rack was over");
  }

  // The other side broke the protocol: tell it why and drop it; it may rejoin. (When the
  // peer already took a new link from the same player, the old one is gone unheard.)
  [[noreturn]] void refusePeer(const std::string& why) {
    logger("net")->warn("the other side sent {}: disconnected it", cleanText(why, 400));
    forgetOldLink();
    if (!rejoinQueued()) {
      send(Refuse{"disconnected: you sent " + why});
      peer_->flush(0.5);
      lost_ = "it sent " + why;
      peer_->lose(lost_);
    }
    throw Dropped{};
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

  // The next message from the peer; nothing once the link is lost (lost_ says why). The host
  // hears newcomers throughout: the other player back on a new connection (its old one dead
  // without our knowing yet, or its program restarted) takes the seat, and the rack goes on
  // through a rejoin.
  std::optional<Message> next() {
    while (true) {
      if (events_.empty() && turn_deadline_ > 0.0 && seconds() > turn_deadline_) {
        const std::string why = "no turn within " + std::to_string(static_cast<int>(o_.turn_s)) +
                                " s: the rack is given up";
        send(Bye{why, false});
        peer_->flush(0.5);
        end(Outcome::LinkLost, "the other player played " + why);
      }
      if (events_.empty()) {
        leaveIfAsked();
        poll();
        if (events_.empty()) nap();
        continue;
      }
      if (rejoinQueued()) {
        lost_ = "the other player connected again";
        return std::nullopt;
      }
      PeerEvent e = std::move(events_.front());
      events_.pop_front();
      if (auto* lost = std::get_if<PeerLost>(&e)) {
        lost_ = lost->reason;
        return std::nullopt;
      }
      if (const auto* bad = std::get_if<PeerBadMessage>(&e)) {
        refusePeer("a bad message (" + bad->why + ")");
      }
      const auto* in = std::get_if<PeerMessage>(&e);
      if (!in) continue;
      const Message& m = in->message;
      if (std::holds_alternative<Aim>(m) || std::holds_alternative<Rematch>(m)) continue;
      if (const auto* r = std::get_if<Refuse>(&m)) {
        end(Outcome::Refused, "the other side refused: " + r->reason);
      }
      return m;
    }
  }

  // A lost link: the rack pauses, and goes on if the peer comes back in time.
  void recover() {
    const std::string reason = lost_;
    if (!allowance_.takeRejoin()) {
      end(Outcome::LinkLost, "the link was lost (" + reason + ") more than " +
                                 std::to_string(o_.most_rejoins) + " times in this rack");
    }
    logger("net")->warn("link lost ({}): waiting up to {} s for a rejoin", reason, o_.rejoin_s);
    const bool back = o_.side == Side::Host ? awaitJoiner() : join();
    if (!back) end(Outcome::LinkLost, "the link was lost (" + reason + ") and not rejoined");
    logger("net")->info("rejoined after turn {}", lockstep_->turns().size());
  }

  // A message from the peer; a lost link throws Dropped (the rack then waits for a rejoin).
  Message nextOrDrop() {
    auto m = next();
    if (!m) throw Dropped{};
    if (const auto* bye = std::get_if<Bye>(&*m)) {
      if (bye->finished && byeBelieved()) {
        end(Outcome::InStep, "the other side's rack is played: " + bye->reason);
      }
      end(Outcome::LinkLost, "the other player left: " + bye->reason);
    }
    return *m;
  }

  // A peer's "finished" is believed only where a rack can end for it: the rack is over here
  // too, or the peer's own script ran out at its move. Anywhere else it is a quit.
  bool byeBelieved() {
    if (match_->rack().over() || records_.size() >= kMaxTurns) return true;
    return lockstep_->settled() && match_->rack().shooter() != lockstep_->localSeat();
  }

  // --- the handshake ---

  // The host: the first newcomer the gate lets in is welcomed to the match (the rack as it
  // stands, when it is a rejoin), or the wait (the rejoin window) runs out.
  bool awaitJoiner() {
    while (true) {
      PeerEvent e = nextEvent();
      if (auto* joined = std::get_if<PeerJoined>(&e)) {
        welcome(joined->hello);
        return true;
      }
      if (std::holds_alternative<PeerTimedOut>(e)) break;
    }
    const double limit = match_ ? o_.rejoin_s : o_.wait_s;
    if (!match_ && !peer_->buildRefusal().empty()) {
      // The host's friend knew the code but runs another build: say so, not "nobody".
      result_.outcome = Outcome::Refused;
      result_.why = "refused the other side: " + peer_->buildRefusal();
      return false;
    }
    result_.outcome = Outcome::NoPeer;
    result_.why = "nobody joined within " + std::to_string(static_cast<int>(limit)) + " s";
    return false;
  }

  void welcome(const Hello& hello) {
    peer_name_ = hello.name;
    if (!match_) startRack(o_.script.setup);
    lockstep_->setPeerPlayer(hello.player);
    peer_->handshakeDone();
    send(welcomeFrom(o_.name, o_.match, Race{}, *lockstep_, peer_->seatToken()));
    lockstep_->rejoined();
    if (const auto h = lockstep_->lastHash()) send(*h);
    logger("net")->info("{} joined", peer_name_);
  }

  // The joiner: the peer reaches the host (again and again until its wait, or the rejoin
  // window, runs out) and says hello; the first answer is a welcome, whose rack is replayed,
  // or a refusal.
  bool join() {
    std::string why = "nobody answered";
    while (true) {
      PeerEvent e = nextEvent();
      if (const auto* u = std::get_if<PeerUnreachable>(&e)) {
        why = u->why;
      } else if (const auto* lost = std::get_if<PeerLost>(&e)) {
        why = "the host closed the link (" + lost->reason + ")";
      } else if (const auto* t = std::get_if<PeerTimedOut>(&e)) {
        if (t->what == PeerTimedOut::What::NoWelcome) {
          why = "the host did not answer the hello";
          continue;
        }
        break;
      } else if (const auto* bad = std::get_if<PeerBadMessage>(&e)) {
        send(Refuse{"a bad first message (" + bad->why + ")"});
        peer_->flush(0.5);
        peer_->lose("it sent a bad first message", true);
      } else if (const auto* in = std::get_if<PeerMessage>(&e)) {
        if (acceptWelcome(in->message)) return true;
        if (result_.outcome == Outcome::Refused) return false;
        why = result_.why.empty() ? why : result_.why;
      }
    }
    // Nobody answered, or only "busy" or silence did (a bad welcome has said LinkLost).
    if (result_.outcome == Outcome::InStep) {
      result_.outcome = Outcome::NoPeer;
      result_.why = why;
    }
    return false;
  }

  // The host's first answer: a welcome (its rack replayed here) or a refusal. Anything else
  // refuses the link, and the peer tries again.
  bool acceptWelcome(const Message& m) {
    if (const auto* r = std::get_if<Refuse>(&m)) {
      result_.why = "the host refused: " + r->reason;
      // A full host is tried again; any other refusal is final.
      if (!isBusyRefusal(r->reason)) result_.outcome = Outcome::Refused;
      peer_->lose(r->reason, true);
      return false;
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
        return false;
      }
    }
    const auto setup = w ? setupOf(*w, why) : std::nullopt;
    if (!setup || !replay(*setup, *w, why)) {
      send(Refuse{"a bad welcome (" + why + ")"});
      peer_->flush(0.5);
      peer_->lose("it sent a bad welcome", true);
      result_.outcome = Outcome::LinkLost;
      result_.why = "the host sent a bad welcome (" + why + ")";
      return false;
    }
    peer_name_ = w->name;
    token_ = w->token;
    peer_->setSeatToken(token_);
    if (o_.on_seat_token) o_.on_seat_token(token_);
    peer_->handshakeDone();
    if (const auto h = lockstep_->lastHash()) send(*h);
    return true;
  }

  Seat localPlayer() const { return o_.script.players[o_.side == Side::Host ? 0 : 1]; }

  // The joiner: the rack from its start, the welcome's turns played again. Between turns the
  // link is kept alive and Ctrl-C heard; a turn after one that left balls moving (the rack
  // was over there) refuses the welcome.
  bool replay(const MatchSetup& setup, const Welcome& w, std::string& why) {
    startRack(setup);
    std::vector<std::uint64_t> hashes;
    for (std::size_t i = 0; i < w.turns.size(); ++i) {
      leaveIfAsked();
      keepAlive();
      if (rackDone()) {
        why = "turns[" + std::to_string(i) + "] comes after the rack was over";
        return false;
      }
      const auto input = parseWireTurn(w.turns[i], setup, why);
      if (!input) return false;
      const CheckedTurn turn{*input, w.turns[i].player};
      try {
        play(turn);
      } catch (const IllegalAction& e) {
        why = "turns[" + std::to_string(i) + "] does not replay: " + e.what();
        return false;
      }
      hashes.push_back(snapshotHash(match_->snapshot()));
    }
    lockstep_->adopt(w.turns, hashes);
    if (!hashes.empty() && hashes.back() != w.hashes.back()) {
      logger("net")->warn("the replayed rack differs from the host's: it will be healed");
    }
    return true;
  }

  // --- the rack ---

  void startRack(const MatchSetup& setup) {
    match_ = std::make_unique<Match>(setup);
    lockstep_ = std::make_unique<Lockstep>(o_.side, setup);
    records_.clear();
    computer_.clear();
    next_script_turn_ = 0;
    partial_ = false;
    const rules::Player seat = lockstep_->localSeat();
    const Seat& mine = o_.script.players[seat == rules::Player::A ? 0 : 1];
    // A rejoin keeps the computer's stream of cueing errors where it was.
    if (planner_) return;
    if (const auto level = computerLevel(mine)) {
      planner_ = std::make_unique<ai::Planner>(*level, plannerSeed(setup.seed, seat));
    }
  }

  void play(const CheckedTurn& turn) {
    records_.push_back(match_->play(turn.input));
    computer_.emplace_back();
    if (const auto level = computerLevel(turn.player)) {
      computer_.back() = io::ComputerTurn{*level, turn.input};
    } else if (records_.back().shooter == lockstep_->localSeat()) {
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

  void playRack() {
    while (true) {
      try {
        settle();
        if (rackDone()) break;
        if (lockstep_->localToMove(*match_)) {
          playLocalTurn();
        } else {
          playPeerTurn();
        }
      } catch (const Dropped&) {
        recover();
      }
    }
    send(Bye{"the rack is played", true});
    end(partial_ ? Outcome::Partial : Outcome::InStep, "the rack is played");
  }

  // Keeps the link alive (pings out, messages in for later) while this side thinks.
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
      end(Outcome::InStep, "this side's script has no turn left");
    }
    const Seat player = planner_ ? Seat{ComputerSeat{planner_->level()}} : Seat{HumanSeat{}};
    TurnMessage message;
    const CheckedTurn turn = lockstep_->localTurn(*choice, player, message);
    const std::size_t script_turn = next_script_turn_;
    try {
      play(turn);
    } catch (const IllegalAction& e) {
      const std::string why = planner_ ? std::string("the computer's turn was refused: ") + e.what()
                                       : "turns[" + std::to_string(script_turn) + "]: " + e.what();
      send(Bye{"my turn was refused", false});
      peer_->flush(0.5);
      records_.pop_back();
      end(Outcome::BadTurn, why);
    }
    if (o_.drop_before_turn && o_.drop_before_turn(message.index)) {
      peer_->closeLink("dropped by the test");
    }
    send(message);
    afterTurn(message.turn);
  }

  void afterTurn(const WireTurn& turn) {
    if (o_.after_turn) o_.after_turn(*match_, records_.size() - 1);
    send(lockstep_->played(turn, match_->snapshot()));
  }

  void playPeerTurn() {
    turn_deadline_ = seconds() + o_.turn_s;
    const Message m = nextOrDrop();
    turn_deadline_ = 0.0;
    const auto* t = std::get_if<TurnMessage>(&m);
    if (!t) refusePeer("a message other than a turn when its turn was due");
    std::string why;
    const auto turn = lockstep_->peerTurn(*t, *match_, why);
    if (!turn) refusePeer(why);
    try {
      play(*turn);
    } catch (const IllegalAction& e) {
      refusePeer(std::string("a turn the rules refuse (") + e.what() + ")");
    }
    afterTurn(t->turn);
  }

  // Waits until both sides agree on the last turn, healing a difference.
  void settle() {
    while (!lockstep_->settled()) {
      const Message m = nextOrDrop();
      std::string why;
      if (const auto* h = std::get_if<HashMessage>(&m)) {
        const auto verdict = lockstep_->peerHash(*h, why);
        if (!verdict) refusePeer(why);
        onVerdict(*verdict, h->index);
      } else if (const auto* s = std::get_if<StateMessage>(&m)) {
        heal(*s);
      } else {
        refusePeer("a message other than a hash while the last turn was being checked");
      }
    }
  }

  void onVerdict(HashVerdict verdict, std::size_t index) {
    if (verdict == HashVerdict::Mismatch && o_.side == Side::Host) {
      if (allowance_.healsSpent(lockstep_->heals())) tooManyHeals(index);
      logger("net")->warn("out of step after turn {}: sending this side's state whole", index);
      const MatchSnapshot own = match_->snapshot();
      send(lockstep_->healMessage(own));
      match_->restore(own);
    } else if (verdict == HashVerdict::Mismatch) {
      logger("net")->warn("out of step after turn {}: waiting for the host's state", index);
    } else if (verdict == HashVerdict::Unhealed) {
      send(Bye{"out of step after turn " + std::to_string(index) + ", and the heal did not take",
               false});
      peer_->flush(0.5);
      end(Outcome::OutOfStep, "the peers fell out of step after turn " + std::to_string(index) +
                                  " and the host's state did not heal it");
    }
  }

  [[noreturn]] void tooManyHeals(std::size_t index) {
    const std::string why = "out of step after turn " + std::to_string(index) + ", healed " +
                            std::to_string(lockstep_->heals()) + " times in this rack already";
    send(Bye{why, false});
    peer_->flush(0.5);
    end(Outcome::OutOfStep, why);
  }

  void heal(const StateMessage& s) {
    if (allowance_.healsSpent(lockstep_->heals())) tooManyHeals(s.index);
    std::string why;
    auto snapshot = lockstep_->healState(s, *match_, why);
    if (!snapshot) refusePeer(why);
    if (o_.on_heal) o_.on_heal(*snapshot);
    match_->restore(*snapshot);
    bool took = false;
    send(lockstep_->healed(*snapshot, took));
    logger("net")->warn("took the host's state after turn {}", s.index);
    if (!took) {
      peer_->flush(0.5);
      end(Outcome::OutOfStep, "the peers fell out of step after turn " + std::to_string(s.index) +
                                  " and the host's state did not heal it");
    }
  }

  void describeRack() {
    result_.heals = lockstep_->heals();
    result_.doc = io::matchResultToJson(records_, match_->rack(), match_->balls(), computer_);
    result_.doc["partial"] = partial_;
    nlohmann::ordered_json hashes = nlohmann::ordered_json::array();
    for (std::uint64_t h : lockstep_->hashes()) hashes.push_back(hashText(h));
    result_.doc["hashes"] = hashes;
  }

  const OnlineRackOptions& o_;
  OnlineRackResult result_;
  std::unique_ptr<Peer> peer_;    // the link, the gate, the handshake's timing, the rejoin window
  std::deque<PeerEvent> events_;  // what the peer reported, not yet acted on
  std::string lost_;              // why the link was lost (the rejoin's reason)
  std::string token_;             // the joiner: its seat token
  RackAllowance allowance_;       // the heals and rejoins this rack may take
  double turn_deadline_ = 0.0;    // the peer's turn must have come by then (0: not waiting)
  std::unique_ptr<Match> match_;
  std::unique_ptr<Lockstep> lockstep_;
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
