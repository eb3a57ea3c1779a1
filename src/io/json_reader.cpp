#include "io/json_reader.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "io/json_fields.hpp"

namespace nineball::io {
namespace {

using nlohmann::json;

/// Builds the document like nlohmann's own DOM parser, but knows the path of the value being
/// read, so that errors nlohmann reports without one (overflow) or not at all (duplicate keys)
/// can name the field.
class PathTrackingBuilder {
 public:
  using string_t = json::string_t;

  PathTrackingBuilder() = default;
  // A document cut short (by a syntax error, or by memory running out) is freed without
  // allocating.
  ~PathTrackingBuilder() { dismantle(root_); }
  PathTrackingBuilder(const PathTrackingBuilder&) = delete;
  PathTrackingBuilder& operator=(const PathTrackingBuilder&) = delete;

  bool null() { return add(nullptr); }
  bool boolean(bool v) { return add(v); }
  bool number_integer(json::number_integer_t v) { return add(v); }
  bool number_unsigned(json::number_unsigned_t v) { return add(v); }
  bool number_float(json::number_float_t v, const string_t& /*text*/) { return add(v); }
  bool string(string_t& v) { return add(std::move(v)); }
  bool binary(json::binary_t& v) { return add(std::move(v)); }

  bool start_object(std::size_t /*size*/) { return open(json::value_t::object); }
  bool start_array(std::size_t /*size*/) { return open(json::value_t::array); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(string_t& k) {
    Frame& f = frames_.back();
    f.key = k;
    if (f.container->contains(k)) {
      error_ = ParseError{path() + ": duplicate key"};
      return false;
    }
    return true;
  }

  bool parse_error(std::size_t /*position*/, const std::string& token, const json::exception& e) {
    // Id 406 is "number overflow": the lexer read a literal no double can hold.
    if (e.id == 406) {
      error_ = ParseError{path() + ": number " + shortened(token) + " is out of range"};
    } else {
      // nlohmann quotes what it last read, which may be a whole 100 kB token.
      error_ = ParseError{"invalid JSON: " + shortened(withoutPrefix(e.what()), 200)};
    }
    return false;
  }

  json takeRoot() { return std::move(root_); }
  ParseError takeError() {
    return error_.message.empty() ? ParseError{"invalid JSON"} : std::move(error_);
  }

 private:
  struct Frame {
    json* container;
    std::string key;  // the key being read, for objects
  };

  static std::string withoutPrefix(const std::string& what) {
    // nlohmann prefixes "[json.exception.parse_error.101] ", which means nothing to a user.
    const auto end = what.find("] ");
    return what.rfind("[json.exception.", 0) == 0 && end != std::string::npos ? what.substr(end + 2)
                                                                              : what;
  }

  template <typename T>
  json* place(T&& v) {
    if (frames_.empty()) {
      root_ = json(std::forward<T>(v));
      return &root_;
    }
    Frame& f = frames_.back();
    if (f.container->is_array()) {
      f.container->emplace_back(std::forward<T>(v));
      return &f.container->back();
    }
    json& slot = (*f.container)[f.key];
    slot = json(std::forward<T>(v));
    return &slot;
  }

  template <typename T>
  bool add(T&& v) {
    place(std::forward<T>(v));
    return true;
  }

  bool open(json::value_t type) {
    frames_.push_back(Frame{place(type), {}});
    return true;
  }

  bool close() {
    frames_.pop_back();
    return true;
  }

  std::string path() const {
    std::string p;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.container->is_array()) {
        // An open child is already the array's last element; a scalar is about to be added.
        const bool child_open = i + 1 < frames_.size();
        p += "[" + std::to_string(f.container->size() - (child_open ? 1 : 0)) + "]";
      } else {
        p += (p.empty() ? "" : ".") + shortened(f.key);
      }
    }
    return p.empty() ? "scene" : p;
  }

  json root_;
  std::vector<Frame> frames_;
  ParseError error_;
};

// Deeper than any document nineball reads (a recorded shot's samples are five levels down),
// with room; a deeper one is left to nlohmann's destructor below it.
constexpr int kDismantledDepth = 8;

void dismantleTo(json& v, int depth) {
  if (depth == 0) return;
  if (v.is_array()) {
    for (json& element : v.get_ref<json::array_t&>()) dismantleTo(element, depth - 1);
    v.get_ref<json::array_t&>().clear();
  } else if (v.is_object()) {
    for (auto& member : v.get_ref<json::object_t&>()) dismantleTo(member.second, depth - 1);
    v.get_ref<json::object_t&>().clear();
  }
}

}  // namespace

void dismantle(json& v) {
  dismantleTo(v, kDismantledDepth);
}

json readJson(std::string_view text) {
  const bool blank = std::all_of(text.begin(), text.end(), [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
  });
  if (blank) throw ParseError{"invalid JSON: empty input"};
  // nlohmann's lexer would stop at a NUL byte and ignore whatever follows it.
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    throw ParseError{"invalid JSON: a NUL byte at offset " + std::to_string(nul)};
  }
  PathTrackingBuilder builder;
  if (!json::sax_parse(text.begin(), text.end(), &builder)) throw builder.takeError();
  return builder.takeRoot();
}

}  // namespace nineball::io
