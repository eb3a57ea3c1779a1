#pragma once

#include <SFML/Graphics/RenderTarget.hpp>

#include "nineball/table.hpp"
#include "render/triangle_batch.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// The table to scale from the physics geometry: wooden rails with diamonds, cushions, the
/// pocket openings between their jaws, the cloth, the head string and the foot spot.
class TablePainter {
 public:
  /// Rebuilds the picture for a table and a window size.
  void build(const TableGeometry& table, const ViewTransform& view);
  void draw(sf::RenderTarget& target) const { batch_.draw(target); }

 private:
  TriangleBatch batch_;
};

}  // namespace nineball::render
