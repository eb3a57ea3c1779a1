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
#include "nineball/planner.hpp"

namespace nineball::net {
namespace {

using Outcome = OnlineRackResult::Outcome;

// However the players play, a rack stops after this many turns (as `nineball match`).
constexpr std::size_t kMaxTurns = kMostTurns;
// How long the host waits for a connected peer's hello, and the joiner for the welcome.
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

class OnlineRack {
 public:
  explicit OnlineRack(const OnlineRackOptions& o) : o_(o), token_(o.seat_token) {}

  OnlineRackResult run() {
    try {
      if (!(o_.side == Side::Host ? listen() && awaitJoiner(o_.wait_s) : join(o_.wait_s))) {
        return result_;
      }
      playRack();
    } catch (const Stop&) {
    }
    if (match_) describeRack();
    // What the peer said reaches the terminal: without control characters.
    result_.why = cleanText(result_.why, std::string::npos);
    if (link_ && !link_->closed()) {
      link_->flush(1.0);
      // The side that closes first holds its port for a minute (TCP's TIME_WAIT), and SFML's
      // listener cannot reuse a held port: the host lets the joiner close first, so it can
      // host again at once.
      if (o_.side == Side::Host) awaitClose(1.0);
      link_->close("done");
    }
    return result_;
  }

 private:
  double seconds() const { return o_.clock->now(); }

  // --- the link ---

  void awaitClose(double limit) {
    const double deadline = seconds() + limit;
    while (!link_->closed() && seconds() < deadline) {
      link_->pump(seconds());
      nap();
    }
  }

  [[noreturn]] void end(Outcome outcome, const std::string& why) {
    result_.outcome = outcome;
    result_.why = why;
    logger("net")->info("rack ends: {}", why);
    throw Stop{};
  }

  void send(const Message& m) { link_->send(toJson(m)); }

  // Ctrl-C: the other side hears that this one left, and the rack ends here.
  void leaveIfAsked() {
    if (!o_.quit || !o_.quit->load()) return;
    if (link_ && !link_->closed()) {
      send(Bye{"the other player quit", false});
      link_->flush(0.5);
    }
    end(Outcome::Quit, "quit before the rack was over");
  }

  // The other side broke the protocol: tell it why and drop it; it may rejoin.
  [[noreturn]] void refusePeer(const std::string& why) {
    logger("net")->warn("the other side sent {}: disconnected it", cleanText(why, 400));
    send(Refuse{"disconnected: you sent " + why});
    link_->flush(0.5);
    link_->close("it sent " + why);
    throw Dropped{};
  }

  // The host, while a game is on: someone else connects. The gate hears every newcomer at
  // once, without waiting for any: a hello with the code and the seat's token is the other
  // player back on a new connection (the old one is dead without our knowing yet, or its
  // program was restarted): it takes the seat, and the rack goes on through a rejoin. Anyone
  // else is refused and the game goes on.
  void watchForRejoin() {
    if (!listener_ || !link_ || link_->closed()) return;
    if (auto admitted = gate_->poll(*listener_, seconds())) {
      link_->close("the other player connected again");
      rejoining_ = std::move(admitted);
    }
  }

  // The next message from the peer; nothing once the link has closed.
  std::optional<Message> next() {
    while (true) {
      if (!inbox_.empty()) {
        nlohmann::json j = std::move(inbox_.front());
        inbox_.pop_front();
        std::string why;
        auto m = readMessage(j, why);
        if (!m) refusePeer("a bad message (" + why + ")");
        if (std::holds_alternative<Aim>(*m) || std::holds_alternative<Rematch>(*m)) continue;
        if (const auto* r = std::get_if<Refuse>(&*m)) {
          end(Outcome::Refused, "the other side refused: " + r->reason);
        }
        return m;
      }
      leaveIfAsked();
      if (link_->closed()) return std::nullopt;
      if (turn_deadline_ > 0.0 && seconds() > turn_deadline_) {
        const std::string why = "no turn within " + std::to_string(static_cast<int>(o_.turn_s)) +
                                " s: the rack is given up";
        send(Bye{why, false});
        link_->flush(0.5);
        end(Outcome::LinkLost, "the other player played " + why);
      }
      for (auto& j : link_->pump(seconds())) inbox_.push_back(std::move(j));
      watchForRejoin();
      if (inbox_.empty()) nap();
    }
  }

  // A lost link: the rack pauses, and goes on if the peer comes back in time.
  void recover() {
    const std::string reason = link_->reason();
    if (++rejoins_ > o_.most_rejoins) {
      end(Outcome::LinkLost, "the link was lost (" + reason + ") more than " +
                                 std::to_string(o_.most_rejoins) + " times in this rack");
    }
    logger("net")->warn("link lost ({}): waiting up to {} s for a rejoin", reason, o_.rejoin_s);
    inbox_.clear();
    const bool back = o_.side == Side::Host ? awaitJoiner(o_.rejoin_s) : join(o_.rejoin_s);
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

  bool listen() {
    std::string why;
    listener_ = Listener::open(o_.address.port, why);
    if (!listener_) {
      result_.outcome = Outcome::NoPeer;
      result_.why = why;
      return false;
    }
    gate_ =
        std::make_unique<HostGate>(o_.code.empty() ? makeJoinCode() : o_.code, o_.limits, o_.gate);
    logger("net")->info("hosting on port {}: join with --join {}:{} --code {}", o_.address.port,
                        localAddress(), o_.address.port, gate_->code());
    return true;
  }

  // The host: the first newcomer the gate lets in is welcomed to the match (the rack as it
  // stands, when it is a rejoin). Newcomers are heard at once, however many say nothing.
  bool awaitJoiner(double limit) {
    const double deadline = seconds() + limit;
    while (!rejoining_ && seconds() < deadline) {
      leaveIfAsked();
      rejoining_ = gate_->poll(*listener_, seconds());
      if (!rejoining_) nap();
    }
    if (rejoining_) {
      link_ = std::move(rejoining_->link);
      const Hello hello = rejoining_->hello;
      rejoining_.reset();
      welcome(hello);
      return true;
    }
    if (!match_ && !gate_->buildRefusal().empty()) {
      // The host's friend knew the code but runs another build: say so, not "nobody".
      result_.outcome = Outcome::Refused;
      result_.why = "refused the other side: " + gate_->buildRefusal();
      return false;
    }
    result_.outcome = Outcome::NoPeer;
    result_.why = "nobody joined within " + std::to_string(static_cast<int>(limit)) + " s";
    return false;
  }

  // What a new link says first: waits until it says something, closes, or `limit` passes.
  std::vector<nlohmann::json> firstWords(Connection& c, double limit) {
    const double deadline = seconds() + limit;
    while (seconds() < deadline && !c.closed()) {
      leaveIfAsked();
      auto in = c.pump(seconds());
      if (!in.empty()) return in;
      nap();
    }
    return {};
  }

  // The first message of the host's answer on the joiner's side: a welcome (with the host's
  // hash behind it) or a refusal.
  std::optional<Message> hostsAnswer(double limit) {
    const auto in = firstWords(*link_, limit);
    if (in.empty()) {
      result_.why = link_->closed() ? "the host closed the link (" + link_->reason() + ")"
                                    : "the host did not answer the hello";
      return std::nullopt;
    }
    std::string why;
    auto m = readMessage(in.front(), why);
    if (!m) {
      refuseLink(*link_, "a bad first message (" + why + ")");
      return std::nullopt;
    }
    for (std::size_t i = 1; i < in.size(); ++i) inbox_.push_back(in[i]);
    return m;
  }

  void welcome(const Hello& hello) {
    peer_name_ = hello.name;
    if (!match_) startRack(o_.script.setup);
    lockstep_->setPeerPlayer(hello.player);
    send(welcomeFrom(o_.name, o_.match, Race{}, *lockstep_, gate_->seatToken()));
    lockstep_->rejoined();
    if (const auto h = lockstep_->lastHash()) send(*h);
    logger("net")->info("{} joined from {}", peer_name_, link_->remote());
  }

  // The joiner: reaches the host (again and again until `limit`), says hello, and replays the
  // rack the welcome carries.
  bool join(double limit) {
    const double deadline = seconds() + limit;
    std::string why = "nobody answered";
    while (seconds() < deadline) {
      leaveIfAsked();
      auto socket = connectTo(o_.address, std::min(o_.connect_s, deadline - seconds()), why);
      if (socket) {
        link_ = std::make_unique<Connection>(std::move(socket), seconds(), o_.limits);
        send(helloFrom(o_.name, o_.code, token_, localPlayer()));
        // The answer is awaited within the rejoin's own limit too.
        if (acceptWelcome(std::clamp(deadline - seconds(), 0.5, kHandshakeSeconds))) return true;
        if (result_.outcome == Outcome::Refused) return false;
        why = result_.why.empty() ? why : result_.why;
      }
      std::this_thread::sleep_for(std::chrono::duration<double>(kRetrySeconds));
    }
    // Nobody answered, or only "busy" or silence did (a bad welcome has said LinkLost).
    if (result_.outcome == Outcome::InStep) {
      result_.outcome = Outcome::NoPeer;
      result_.why = why;
    }
    return false;
  }

  bool acceptWelcome(double limit) {
    auto m = hostsAnswer(limit);
    if (!m) return false;
    if (const auto* r = std::get_if<Refuse>(&*m)) {
      result_.why = "the host refused: " + r->reason;
      // A full host is tried again; any other refusal is final.
      if (!isBusyRefusal(r->reason)) result_.outcome = Outcome::Refused;
      return false;
    }
    const auto* w = std::get_if<Welcome>(&*m);
    std::string why;
    if (!w) why = "a first message that is not a welcome";
    if (w) {
      if (const auto r = refusalOf(*w)) {
        send(Refuse{*r});
        link_->flush(0.5);
        result_.outcome = Outcome::Refused;
        result_.why = "refused the host: " + *r;
        return false;
      }
    }
    const auto setup = w ? setupOf(*w, why) : std::nullopt;
    if (!setup || !replay(*setup, *w, why)) {
      send(Refuse{"a bad welcome (" + why + ")"});
      link_->flush(0.5);
      result_.outcome = Outcome::LinkLost;
      result_.why = "the host sent a bad welcome (" + why + ")";
      return false;
    }
    peer_name_ = w->name;
    token_ = w->token;
    if (o_.on_seat_token) o_.on_seat_token(token_);
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
    if (link_->closed()) return;
    for (auto& j : link_->pump(seconds())) inbox_.push_back(std::move(j));
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
      link_->flush(0.5);
      records_.pop_back();
      end(Outcome::BadTurn, why);
    }
    if (o_.drop_before_turn && o_.drop_before_turn(message.index)) {
      link_->close("dropped by the test");
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
      if (lockstep_->heals() >= o_.most_heals) tooManyHeals(index);
      logger("net")->warn("out of step after turn {}: sending this side's state whole", index);
      const MatchSnapshot own = match_->snapshot();
      send(lockstep_->healMessage(own));
      match_->restore(own);
    } else if (verdict == HashVerdict::Mismatch) {
      logger("net")->warn("out of step after turn {}: waiting for the host's state", index);
    } else if (verdict == HashVerdict::Unhealed) {
      send(Bye{"out of step after turn " + std::to_string(index) + ", and the heal did not take",
               false});
      link_->flush(0.5);
      end(Outcome::OutOfStep, "the peers fell out of step after turn " + std::to_string(index) +
                                  " and the host's state did not heal it");
    }
  }

  [[noreturn]] void tooManyHeals(std::size_t index) {
    const std::string why = "out of step after turn " + std::to_string(index) + ", healed " +
                            std::to_string(lockstep_->heals()) + " times in this rack already";
    send(Bye{why, false});
    link_->flush(0.5);
    end(Outcome::OutOfStep, why);
  }

  void heal(const StateMessage& s) {
    if (lockstep_->heals() >= o_.most_heals) tooManyHeals(s.index);
    std::string why;
    auto snapshot = lockstep_->healState(s, *match_, why);
    if (!snapshot) refusePeer(why);
    if (o_.on_heal) o_.on_heal(*snapshot);
    match_->restore(*snapshot);
    bool took = false;
    send(lockstep_->healed(*snapshot, took));
    logger("net")->warn("took the host's state after turn {}", s.index);
    if (!took) {
      link_->flush(0.5);
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
  std::unique_ptr<Listener> listener_;
  std::unique_ptr<Connection> link_;
  std::unique_ptr<HostGate> gate_;     // the host: who may sit down
  std::optional<Admitted> rejoining_;  // the other player back on a new connection
  std::string token_;                  // the joiner: its seat token
  int rejoins_ = 0;
  double turn_deadline_ = 0.0;  // the peer's turn must have come by then (0: not waiting)
  std::deque<nlohmann::json> inbox_;
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
