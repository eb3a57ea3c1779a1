#pragma once

#include <SFML/Graphics/Image.hpp>

#include "nineball/table.hpp"
#include "render/view_transform.hpp"

namespace nineball::render {

/// The materials over the table's flat colours, once per window size: the cloth's fine nap
/// and the soft pool of light over the bed, the cushions' felt, the rails' wood grain running
/// along each rail, the diamonds' pearl. Each is found by the flat colour TablePainter gave it
/// (its shapes are drawn without blending, so the colours are exact).
void finishTable(sf::Image& picture, const ViewTransform& view, const TableGeometry& table);

}  // namespace nineball::render
