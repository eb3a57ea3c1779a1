#pragma once

namespace nineball {

/// The six pockets (top = +y, right = +x). Its own header so the rules can name pockets
/// without the table's geometry.
enum class PocketId { TopLeft, TopSide, TopRight, BottomRight, BottomSide, BottomLeft };
constexpr int kPocketCount = 6;

}  // namespace nineball
