#include "window/state_file.hpp"

#include <filesystem>
#include <fstream>
#include <system_error>

#include "common/atomic_file.hpp"
#include "window/player_name.hpp"

namespace nineball::window {

bool saveStateFile(const std::string& path, const std::string& text, const std::string& no_home,
                   std::string& why) {
  if (path.empty()) {
    why = no_home;
    return false;
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) {
    why = "cannot make " + folder.string() + ": " + ec.message();
    return false;
  }
  return writeFileAtomically(path, text, why);
}

bool readStateFile(const std::string& path, std::string& text, std::string& why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = "cannot read it";
    return false;
  }
  text.assign(kMaxStateFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxStateFileBytes) {
    why = "larger than " + std::to_string(kMaxStateFileBytes >> 20) + " MiB";
    return false;
  }
  return true;
}

std::string printable(const std::string& s) {
  if (validUtf8(s)) return s;
  std::string out;
  for (char c : s) out += static_cast<unsigned char>(c) < 0x80 ? c : '?';
  return out;
}

}  // namespace nineball::window
