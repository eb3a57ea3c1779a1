#include "physics/resolve/cushion/stronge_compliant/stronge_compliant.hpp"

#include <algorithm>
#include <cmath>

#include "physics/resolve/cushion/contact.hpp"

namespace nineball::physics {
namespace {

constexpr double kHalfPi = kPi / 2.0;

// Tangential over normal inverse mass of a solid sphere at a point of its surface, the normal
// through its centre: beta_t = 1 + m R^2 / I = 7/2, beta_n = 1 (pooltool's beta_t = 3.5,
// beta_n = 1 for the sphere on a half-space).
constexpr double kBeta = 3.5;

// omega_t / omega_n, the tangential spring's frequency over the normal one's: pooltool's
// default, raised from 1.7 to 1.8 when this model became its default (its PR #256, "after some
// experimentation"). It sets k_n / k_t = eta^2 = beta / ratio^2 = 1.08. Stronge's analysis of
// the phases needs it in (1, 2); this solver does not, but the constant stays there.
constexpr double kOmegaRatio = 1.8;

// The nose at most this high on the ball (sin theta): the model refuses noses outside
// R <= h < 2 R (strongeHeightFault); the cap only keeps the normal approach speed, cos(theta) vy,
// away from zero for any other input.
constexpr double kMaxSinTheta = 0.999;

// Samples of the rest of a sticking phase, searched for the first instant the spring needs
// more than the friction gives. The instant can fall anywhere, and a grid finer than any
// window in which the spring could rise above the cone and fall back under it finds the first
// one: 32 give the rebound of 8192 to 1e-13 over two million random impacts (every e, friction
// up to 10, ratios in (1, 2)).
constexpr int kScan = 32;

// Bisection of the bracketing sample down to this width of the force's phase (rad): the
// rebound then moves by far less than 1e-12 of the approach speed.
constexpr double kPhaseTolerance = 1e-13;

// Stick and slip alternate at most slip-stick-slip in Stronge's analysis; a few more allowed
// phases cost nothing and keep a tangent case (a phase that ends as it starts) from looping.
constexpr int kMaxPhases = 8;

// The impact in Stronge's dimensionless variables: time in 1 / omega_n, velocities in the
// contact's normal approach speed, spring deflections in that speed over omega_n. The normal
// force is sin(phi) times its peak throughout: phi = tau while compressing (0 to pi/2); then
// the stiffer spring runs phi through pi/2 to pi 1/e times as fast, tau = pi/2 + e (phi - pi/2).
// Stepping in phi keeps a small e from dividing anything.
struct Impact {
  double mu;    // cushion friction
  double e;     // normal restitution (energetic, and here kinematic as well)
  double rho;   // omega_t / omega_n
  double eta2;  // k_n / k_t
  double last;  // phi at separation: pi, or pi/2 when e = 0 (restitution takes no time)

  double tau(double phi) const { return phi <= kHalfPi ? phi : kHalfPi + e * (phi - kHalfPi); }
  // The normal impulse since contact, in units of m v / beta_n.
  double impulse(double phi) const {
    return phi <= kHalfPi ? 1.0 - std::cos(phi) : 1.0 - e * std::cos(phi);
  }
  // The largest deflection of the tangential spring the friction holds: mu N / k_t.
  double bound(double phi) const { return mu * eta2 * std::sin(phi); }
};

// Sticking: the contact's tangential velocity s and the spring's deflection u oscillate at rho
// (the spring against the ball's tangential inertia), from (s0, u0) at tau0.
void stuck(const Impact& c, double tau0, double s0, double u0, double phi, double& s, double& u) {
  const double a = c.rho * (c.tau(phi) - tau0);
  const double cs = std::cos(a), sn = std::sin(a);
  s = s0 * cs + c.rho * u0 * sn;
  u = u0 * cs - s0 / c.rho * sn;
}

// A sticking phase from phi0: until the spring needs more than the friction can give,
// |u| > bound, the first such instant found on a grid and bisected. Returns that phi (or
// c.last if it sticks to the end) with s and u there.
double stickPhase(const Impact& c, double phi0, double& s, double& u) {
  const double tau0 = c.tau(phi0), s0 = s, u0 = u;
  auto slips = [&](double phi) {
    double ss = 0.0, uu = 0.0;
    stuck(c, tau0, s0, u0, phi, ss, uu);
    return std::abs(uu) > c.bound(phi);
  };
  double lo = phi0, hi = c.last;
  bool found = false;
  for (int k = 1; k <= kScan && !found; ++k) {
    const double phi = k == kScan ? c.last : phi0 + (c.last - phi0) * k / kScan;
    if (slips(phi)) {
      hi = phi;
      found = true;
    } else {
      lo = phi;
    }
  }
  while (found && hi - lo > kPhaseTolerance) {
    const double mid = 0.5 * (lo + hi);
    if (slips(mid)) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  stuck(c, tau0, s0, u0, hi, s, u);
  return hi;
}

// A slipping phase from phi0, the free end of the spring sliding along sigma: friction
// mu N takes mu beta from s per unit normal impulse, and the spring sits at the cone,
// u = -sigma bound. The end slides at q = s + du/dtau until that reaches 0 and it sticks;
// on either half of the impact sigma q is linear in cos(phi), so the instant is closed form.
// Returns it (or c.last) with s there.
double slipPhase(const Impact& c, double sigma, double phi0, double& s) {
  const double mu = c.mu;
  double phi = phi0;
  if (phi < kHalfPi && phi < c.last) {
    // sigma q = sigma s0 - mu beta (cos phi0 - cos phi) - mu eta2 cos phi: falls with phi.
    const double c0 = std::cos(phi);
    const double x = (mu * kBeta * c0 - sigma * s) / (mu * (kBeta - c.eta2));
    if (x >= c0) return phi;  // not sliding forward: it sticks at once
    if (x >= 0.0) {
      const double end = std::acos(x);
      s -= sigma * mu * kBeta * (c.impulse(end) - c.impulse(phi));
      return end;
    }
    s -= sigma * mu * kBeta * (c.impulse(kHalfPi) - c.impulse(phi));
    phi = kHalfPi;
  }
  if (phi >= c.last) return c.last;
  // e sigma q = e sigma s1 - mu beta e^2 (cos phi1 - cos phi) - mu eta2 cos phi: rises or
  // falls with phi as e^2 beta is below or above eta2.
  const double c1 = std::cos(phi);
  const double start = c.e * sigma * s - mu * c.eta2 * c1;
  if (start <= 0.0) return phi;
  const double d = mu * (kBeta * c.e * c.e - c.eta2);
  if (d > 0.0) {
    const double x = (mu * kBeta * c.e * c.e * c1 - c.e * sigma * s) / d;
    if (x >= -1.0) {
      const double end = std::acos(std::min(x, 1.0));
      s -= sigma * mu * kBeta * (c.impulse(end) - c.impulse(phi));
      return end;
    }
  }
  s -= sigma * mu * kBeta * (c.impulse(c.last) - c.impulse(phi));
  return c.last;
}

}  // namespace

double strongeSlipAfter(double slip, double friction, double restitution, double omega_ratio) {
  const double mu = std::max(friction, 0.0);
  if (slip == 0.0 || !(mu > 0.0)) return slip;
  // Friction opposes the slip whichever way it points: solve for a positive slip.
  const double sign = slip < 0.0 ? -1.0 : 1.0;
  const double r = std::abs(slip);
  const double e = std::clamp(restitution, 0.0, 1.0);
  const double eta2 = kBeta / (omega_ratio * omega_ratio);
  const Impact c{mu, e, omega_ratio, eta2, e > 0.0 ? kPi : kHalfPi};
  // The spring starts relaxed, the normal force at 0: the contact sticks from the start if the
  // friction cone grows faster than the spring would deflect, r <= mu eta^2.
  bool sticking = r <= mu * eta2;
  double phi = 0.0, s = r, u = 0.0, sigma = 1.0;
  for (int n = 0; n < kMaxPhases && phi < c.last; ++n) {
    if (sticking) {
      phi = stickPhase(c, phi, s, u);
      sigma = u > 0.0 ? -1.0 : 1.0;  // the spring pulls the end the other way
    } else {
      phi = slipPhase(c, sigma, phi, s);
      u = -sigma * c.bound(phi);
    }
    sticking = !sticking;
  }
  if (phi < c.last) {
    // Out of phases (a tangent case): stick to the end. Sticking only trades energy between
    // the ball and the spring, where slipping past a stop would let friction drive the ball.
    const double s0 = s, u0 = u;
    stuck(c, c.tau(phi), s0, u0, c.last, s, u);
  }
  // The slip's energy, m s^2 / (2 beta), only falls (friction and the spring's leftover take it);
  // the clamp guards that against rounding alone.
  return sign * std::clamp(s, -r, r);
}

Kinematics strongeBounce(Kinematics k, Vec2 inward, double mass, const PhysicsParams& p,
                         double& impulse) {
  impulse = 0.0;
  // The cushion's frame: x along it, y into it, z up.
  const Vec2 y = inward * -1.0;
  const Vec2 x{y.y, -y.x};  // x cross y = z
  const double vx = dot(k.v, x), vy = dot(k.v, y);
  if (!(vy >= kRestingSpeed)) return k;
  const double wx = k.w.x * x.x + k.w.y * x.y, wy = k.w.x * y.x + k.w.y * y.y, wz = k.w.z;
  const double r = p.ball_radius;
  const double sin_t = std::clamp((p.cushion_height - r) / r, 0.0, kMaxSinTheta);
  const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
  const double e = std::clamp(p.cushion_restitution, 0.0, 1.0);
  // The contact point (0, cos, sin) R from the centre. Spin gives it no speed along the normal,
  // so it meets the cushion at cos(theta) vy. Its slip in the tangent plane: gx along the rail,
  // g2 along (0, sin, -cos), down the nose's face.
  const double approach = vy * cos_t;
  const double gx = vx + r * (wy * sin_t - wz * cos_t);
  const double g2 = vy * sin_t - r * wx;
  const double slip = std::hypot(gx, g2);
  // The sphere's tangential inverse mass is the same in every direction of the tangent plane,
  // so the slip keeps its direction: one scalar impact along it.
  const double ratio = slip / approach;
  double dgx = 0.0, dg2 = 0.0;  // the change in the slip
  if (slip > 0.0) {
    const double after = strongeSlipAfter(ratio, p.cushion_friction, e, kOmegaRatio);
    const double f = (after - ratio) * approach / slip;
    dgx = f * gx;
    dg2 = f * g2;
  }
  // The impulse: (1 + e) m approach along the normal, m dg / beta_t in the tangent plane. Its
  // moment about the centre turns the spin by (5 / 7R) c x dg, c the unit vector to the
  // contact; the vertical velocity it gives is the slate's to take.
  impulse = mass * (1.0 + e) * approach;
  const double vx1 = vx + dgx / kBeta;
  double vy1 = vy - (1.0 + e) * approach * cos_t + dg2 * sin_t / kBeta;
  if (vy1 > 0.0) {
    // Still moving into the cushion once the slate has its vertical velocity: possible only
    // when (1 + e) cos(theta) (cos(theta) - mu sin(theta)) < 1 (e under about 0.14 on the
    // standard nose). The slate, holding the ball up against the nose, stops it there; the
    // nose's impulse that takes the last of vy is counted in the total.
    impulse += mass * vy1 / cos_t;
    vy1 = 0.0;
  }
  const double turn = 5.0 / (7.0 * r);
  const double wx1 = wx - turn * dg2;
  const double wy1 = wy + turn * dgx * sin_t;
  const double wz1 = wz - turn * dgx * cos_t;
  k.v = x * vx1 + y * vy1;
  k.w = {x.x * wx1 + y.x * wy1, x.y * wx1 + y.y * wy1, wz1};
  return k;
}

namespace {

// From the centre's height (the contact of pooltool 0.6.0) to below the top.
std::optional<std::string> strongeHeightFault(const PhysicsParams& p) {
  return noseHeightFault(p, "the Stronge cushion");
}

}  // namespace

CushionModelDef strongeCompliantCushion() {
  CushionModelDef m;
  m.name = "stronge";
  m.bounce = strongeBounce;
  m.reads = {"cushion_height"};
  m.check = strongeHeightFault;
  return m;
}

}  // namespace nineball::physics
