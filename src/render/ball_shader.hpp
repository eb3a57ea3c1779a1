#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/RenderTexture.hpp>
#include <SFML/Graphics/Shader.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <cstdint>

#include "nineball/colours.hpp"
#include "nineball/vec2.hpp"
#include "render/ball_spin.hpp"

namespace nineball::render {

/// One ball as a lit sphere turned to its orientation, its number, stripe and spots drawn
/// where the orientation puts them: by a fragment shader where the graphics driver has one,
/// by the same arithmetic on the CPU (render/ball_spin.cpp) where it has not.
class SphereBallRenderer {
 public:
  /// Numbers are drawn once into a texture of glyphs, with `font`.
  explicit SphereBallRenderer(const sf::Font& font);

  struct Ball {
    BallLook look;
    int number = 0;
    Orientation q;
    Vec2 centre_px;
    double radius_px = 0.0;
    double darken = 0.0;  ///< 0 as lit, 1 black (a ball sinking into a pocket)
    std::uint8_t alpha = 255;
  };
  void draw(sf::RenderTarget& target, const Ball& ball);

  /// True when the shader draws; false on the CPU fallback (no shaders in the driver, or
  /// NINEBALL_NO_SHADERS=1 in the environment).
  bool usesShader() const { return shader_ready_; }

  /// A glyph's coverage at disc coordinates (u, v) in -1..1 (v up), 0-1; what both paths read.
  double ink(int number, double u, double v) const;

 private:
  void buildGlyphs(const sf::Font& font);
  void drawWithShader(sf::RenderTarget& target, const Ball& ball);
  void drawOnCpu(sf::RenderTarget& target, const Ball& ball);

  sf::RenderTexture glyph_target_;
  sf::Image glyphs_;  // the same glyphs, for the CPU
  sf::Texture glyph_texture_;
  sf::Shader shader_;
  bool shader_ready_ = false;
  sf::VertexArray quad_;
  sf::Image cpu_pixels_;
  sf::Texture cpu_texture_;
};

}  // namespace nineball::render
