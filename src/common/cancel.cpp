#include "nineball/cancel.hpp"

namespace nineball {
namespace {

thread_local const std::atomic<bool>* current = nullptr;

}  // namespace

CancelScope::CancelScope(const std::atomic<bool>* flag) : outer_(current) {
  current = flag;
}

CancelScope::~CancelScope() {
  current = outer_;
}

bool cancelRequested() {
  return current != nullptr && current->load(std::memory_order_relaxed);
}

}  // namespace nineball
