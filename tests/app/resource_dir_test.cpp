// Where nineball finds its icon and desktop files: installed beside its bin folder first, then
// the source tree. The installed tree itself is checked by tests/install/installed_tree_test.sh.
#include "app/resource_dir.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using nineball::app::findResourceDir;
using nineball::app::installedResourceDir;
using nineball::app::kIconFile;

namespace {

// A fresh folder under $TMPDIR (or /tmp), removed with everything in it at scope exit.
class TempDir {
 public:
  TempDir() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/nineball_res_XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void putIcon(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / kIconFile) << "png";
}

}  // namespace

TEST(ResourceDir, InstalledFolderIsShareNineballBesideBin) {
  EXPECT_EQ(installedResourceDir("/usr/bin/nineball"), "/usr/share/nineball");
  EXPECT_EQ(installedResourceDir("/opt/x/bin/nineball-game"), "/opt/x/share/nineball");
}

TEST(ResourceDir, TheInstalledFolderComesBeforeTheSourceTree) {
  TempDir tmp;
  putIcon(tmp.path() / "prefix/share/nineball");
  putIcon(tmp.path() / "src/resources");
  const std::string exe = (tmp.path() / "prefix/bin/nineball").string();
  EXPECT_EQ(findResourceDir(exe, (tmp.path() / "src/resources").string()),
            (tmp.path() / "prefix/share/nineball").string());
}

TEST(ResourceDir, WithoutAnInstalledFolderTheSourceTreesIsUsed) {
  TempDir tmp;
  putIcon(tmp.path() / "src/resources");
  const std::string source = (tmp.path() / "src/resources").string();
  EXPECT_EQ(findResourceDir((tmp.path() / "build/nineball").string(), source), source);
  // A folder without the icon is not a resource folder.
  fs::create_directories(tmp.path() / "share/nineball");
  EXPECT_EQ(findResourceDir((tmp.path() / "bin/nineball").string(), source), source);
  // A program that cannot find its own path looks in the source tree only.
  EXPECT_EQ(findResourceDir("", source), source);
}

TEST(ResourceDir, NoFolderWithTheIconGivesNothing) {
  TempDir tmp;
  EXPECT_EQ(findResourceDir((tmp.path() / "bin/nineball").string(),
                            (tmp.path() / "src/resources").string()),
            std::nullopt);
}

TEST(ResourceDir, ThisBuildFindsTheSourceTreesResources) {
  const auto dir = findResourceDir();
  ASSERT_TRUE(dir.has_value());
  EXPECT_TRUE(fs::equivalent(*dir, fs::path(NINEBALL_SOURCE_DIR) / "resources"));
}
