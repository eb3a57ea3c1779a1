#include "render/ball_shader.hpp"

#include <SFML/Graphics/Sprite.hpp>
#include <SFML/Graphics/Text.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "common/log.hpp"
#include "render/sfml_errors.hpp"

namespace nineball::render {
namespace {

// The glyph texture: numbers 0..kGlyphs-1, each centred in a square cell.
constexpr int kGlyphs = 24;
constexpr int kColumns = 6;
constexpr int kCell = 64;

// The shader: render/ball_spin.cpp's litBall and surfaceColour, line for line.
constexpr const char* kFragment = R"(
uniform sampler2D glyphs;
uniform mat3 to_body;
uniform vec4 base;
uniform float stripe;
uniform float numbered;
uniform float cue_spot;
uniform vec4 cell;
uniform float edge;
uniform float darken;
uniform float opacity;
uniform vec3 light;
uniform float stripe_half;
uniform float disc_radius;
uniform vec3 spot_colour;

void main() {
  vec2 s = gl_TexCoord[0].xy;
  float rr = dot(s, s);
  if (rr >= 1.0) discard;
  vec3 n = vec3(s.x, s.y, sqrt(1.0 - rr));
  vec3 b = to_body * n;
  vec3 white = vec3(250.0, 248.0, 240.0) / 255.0;
  vec3 c = base.rgb;
  if (stripe > 0.5 && abs(b.y) > stripe_half) c = white;
  float off = sqrt(max(0.0, 1.0 - b.z * b.z));
  if (numbered > 0.5 && off < disc_radius) {
    float u = (b.z > 0.0 ? b.x : -b.x) / disc_radius;
    float v = b.y / disc_radius;
    vec2 at = vec2(cell.x + (u + 1.0) * 0.5 * cell.z, cell.y + (1.0 - v) * 0.5 * cell.w);
    float k = texture2D(glyphs, at).a;
    c = mix(white, vec3(20.0, 20.0, 20.0) / 255.0, k);
  } else if (cue_spot > 0.5 && off < 0.22) {
    c = spot_colour;
  }
  float diffuse = max(0.0, dot(n, light));
  vec3 h = normalize(light + vec3(0.0, 0.0, 1.0));
  float spec = pow(max(0.0, dot(n, h)), 60.0);
  float lit = 0.42 + 0.68 * diffuse;
  c = min(vec3(1.0), c * lit + vec3(0.55 * spec));
  c *= 1.0 - darken;
  float a = clamp((1.0 - sqrt(rr)) * edge, 0.0, 1.0) * opacity;
  gl_FragColor = vec4(c, a);
}
)";

double inkFrom(const void* renderer, int number, double u, double v) {
  return static_cast<const SphereBallRenderer*>(renderer)->ink(number, u, v);
}

}  // namespace

SphereBallRenderer::SphereBallRenderer(const sf::Font& font) : quad_(sf::TriangleStrip, 4) {
  buildGlyphs(font);
  // NINEBALL_NO_SHADERS=1 draws as a driver without shaders would (and lets the two be compared).
  const char* no_shaders = std::getenv("NINEBALL_NO_SHADERS");
  if (no_shaders && std::string(no_shaders) == "1") {
    logger("render")->info("NINEBALL_NO_SHADERS=1: the balls are drawn on the CPU");
  } else if (sf::Shader::isAvailable()) {
    const SfmlErrorsToLog to_log;
    shader_ready_ = shader_.loadFromMemory(kFragment, sf::Shader::Fragment);
    if (!shader_ready_) logger("render")->warn("ball shader did not compile; drawing on the CPU");
  }
  if (shader_ready_) {
    shader_.setUniform("glyphs", glyph_texture_);
    const Vec3 l = lightDirection();
    shader_.setUniform("light", sf::Glsl::Vec3(static_cast<float>(l.x), static_cast<float>(l.y),
                                               static_cast<float>(l.z)));
    shader_.setUniform("stripe_half", static_cast<float>(kStripeHalfHeight));
    shader_.setUniform("disc_radius", static_cast<float>(kNumberDiscRadius));
    shader_.setUniform("spot_colour", sf::Glsl::Vec3(kCueSpot.r / 255.0f, kCueSpot.g / 255.0f,
                                                     kCueSpot.b / 255.0f));
  }
}

void SphereBallRenderer::buildGlyphs(const sf::Font& font) {
  const int rows = (kGlyphs + kColumns - 1) / kColumns;
  glyphs_.create(kColumns * kCell, rows * kCell, sf::Color::Transparent);
  if (glyph_target_.create(kColumns * kCell, rows * kCell)) {
    glyph_target_.clear(sf::Color::Transparent);
    for (int n = 0; n < kGlyphs; ++n) {
      sf::Text t(std::to_string(n), font, kCell);
      t.setFillColor(sf::Color::Black);
      const sf::FloatRect b = t.getLocalBounds();
      const double scale = glyphScale(b.width, b.height, kCell);
      t.setOrigin(b.left + b.width / 2.0f, b.top + b.height / 2.0f);
      t.setScale(static_cast<float>(scale), static_cast<float>(scale));
      t.setPosition(static_cast<float>((n % kColumns + 0.5) * kCell),
                    static_cast<float>((n / kColumns + 0.5) * kCell));
      glyph_target_.draw(t);
    }
    glyph_target_.display();
    glyphs_ = glyph_target_.getTexture().copyToImage();
  }
  glyph_texture_.loadFromImage(glyphs_);
  glyph_texture_.setSmooth(true);
}

double SphereBallRenderer::ink(int number, double u, double v) const {
  if (number < 0 || number >= kGlyphs) return 0.0;
  const double x = (number % kColumns + (u + 1.0) * 0.5) * kCell;
  const double y = (number / kColumns + (1.0 - v) * 0.5) * kCell;
  const auto px = static_cast<unsigned>(std::clamp(x, 0.0, kColumns * kCell - 1.0));
  const auto py = static_cast<unsigned>(std::clamp(y, 0.0, glyphs_.getSize().y - 1.0));
  if (px >= glyphs_.getSize().x || py >= glyphs_.getSize().y) return 0.0;
  return glyphs_.getPixel(px, py).a / 255.0;
}

void SphereBallRenderer::draw(sf::RenderTarget& target, const Ball& ball) {
  if (shader_ready_) {
    drawWithShader(target, ball);
  } else {
    drawOnCpu(target, ball);
  }
}

void SphereBallRenderer::drawWithShader(sf::RenderTarget& target, const Ball& ball) {
  // One pixel of room for the soft rim; texture coordinates in radii, y towards the top rail.
  const double r = ball.radius_px + 1.0;
  const double k = r / ball.radius_px;
  const Vec2 c = ball.centre_px;
  const Vec2 corners[4] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
  for (int i = 0; i < 4; ++i) {
    const Vec2 p = corners[i];
    quad_[static_cast<std::size_t>(i)].position =
        sf::Vector2f(static_cast<float>(c.x + p.x * r), static_cast<float>(c.y + p.y * r));
    quad_[static_cast<std::size_t>(i)].texCoords =
        sf::Vector2f(static_cast<float>(p.x * k), static_cast<float>(-p.y * k));
    quad_[static_cast<std::size_t>(i)].color = sf::Color::White;
  }
  // The columns of the table-to-body rotation.
  const Vec3 ex = ball.q.toBody({1, 0, 0}), ey = ball.q.toBody({0, 1, 0}),
             ez = ball.q.toBody({0, 0, 1});
  const float m[9] = {static_cast<float>(ex.x), static_cast<float>(ex.y), static_cast<float>(ex.z),
                      static_cast<float>(ey.x), static_cast<float>(ey.y), static_cast<float>(ey.z),
                      static_cast<float>(ez.x), static_cast<float>(ez.y), static_cast<float>(ez.z)};
  shader_.setUniform("to_body", sf::Glsl::Mat3(m));
  const Rgb col = ball.look.colour;
  shader_.setUniform("base", sf::Glsl::Vec4(col.r / 255.0f, col.g / 255.0f, col.b / 255.0f, 1.0f));
  shader_.setUniform("stripe", ball.look.stripe ? 1.0f : 0.0f);
  shader_.setUniform("numbered", ball.look.numbered ? 1.0f : 0.0f);
  shader_.setUniform("cue_spot", ball.look.spots ? 1.0f : 0.0f);
  const auto size = glyph_texture_.getSize();
  const int n = std::clamp(ball.number, 0, kGlyphs - 1);
  shader_.setUniform("cell", sf::Glsl::Vec4(static_cast<float>((n % kColumns) * kCell) / size.x,
                                            static_cast<float>((n / kColumns) * kCell) / size.y,
                                            static_cast<float>(kCell) / size.x,
                                            static_cast<float>(kCell) / size.y));
  shader_.setUniform("edge", static_cast<float>(ball.radius_px));
  shader_.setUniform("darken", static_cast<float>(ball.darken));
  shader_.setUniform("opacity", ball.alpha / 255.0f);
  target.draw(quad_, sf::RenderStates(&shader_));
}

void SphereBallRenderer::drawOnCpu(sf::RenderTarget& target, const Ball& ball) {
  const int half = static_cast<int>(std::ceil(ball.radius_px)) + 1;
  const auto side = static_cast<unsigned>(2 * half);
  if (cpu_pixels_.getSize().x != side) {
    cpu_pixels_.create(side, side, sf::Color::Transparent);
    cpu_texture_.create(side, side);
  }
  const Vec2 c = ball.centre_px;
  // The disc's centre within the picture, to the sub-pixel, so that it lands where it should.
  const double ox = c.x - (std::floor(c.x) - half), oy = c.y - (std::floor(c.y) - half);
  for (unsigned y = 0; y < side; ++y) {
    for (unsigned x = 0; x < side; ++x) {
      const double sx = (x + 0.5 - ox) / ball.radius_px, sy = -(y + 0.5 - oy) / ball.radius_px;
      const Shade s =
          litBall(ball.look, ball.number, ball.q, sx, sy, ball.radius_px, inkFrom, this);
      const double keep = 1.0 - ball.darken;
      cpu_pixels_.setPixel(x, y,
                           sf::Color(static_cast<sf::Uint8>(std::lround(255.0 * s.r * keep)),
                                     static_cast<sf::Uint8>(std::lround(255.0 * s.g * keep)),
                                     static_cast<sf::Uint8>(std::lround(255.0 * s.b * keep)),
                                     static_cast<sf::Uint8>(std::lround(s.a * ball.alpha))));
    }
  }
  cpu_texture_.update(cpu_pixels_);
  sf::Sprite sprite(cpu_texture_);
  sprite.setPosition(static_cast<float>(std::floor(c.x) - half),
                     static_cast<float>(std::floor(c.y) - half));
  target.draw(sprite);
}

}  // namespace nineball::render
