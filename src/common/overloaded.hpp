#pragma once

namespace nineball {

/// One lambda per alternative for std::visit: `std::visit(Overloaded{[](A) {...}, [](B) {...}},
/// v)`.
template <class... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace nineball
