// Files are written whole or not at all, under a unique temporary name, never through a
// symlink, and nothing is left behind on failure.
#include "common/atomic_file.hpp"

#include <dirent.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace nineball {
namespace {

class ScratchDir {
 public:
  ScratchDir() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/nineball_atomic_XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~ScratchDir() {
    for (const std::string& name : entries()) ::unlink((path_ + "/" + name).c_str());
    ::rmdir(path_.c_str());
  }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  std::vector<std::string> entries() const {
    std::vector<std::string> out;
    if (DIR* d = ::opendir(path_.c_str())) {
      while (const dirent* e = ::readdir(d)) {
        const std::string n = e->d_name;
        if (n != "." && n != "..") out.push_back(n);
      }
      ::closedir(d);
    }
    return out;
  }

 private:
  std::string path_;
};

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writePlain(const std::string& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

TEST(AtomicFile, WritesTheWholeContentAndLeavesNothingElse) {
  ScratchDir dir;
  std::string why;
  const std::string content(1 << 20, 'x');
  ASSERT_TRUE(writeFileAtomically(dir.file("out.csv"), content, why)) << why;
  EXPECT_EQ(readAll(dir.file("out.csv")), content);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.csv"});
}

TEST(AtomicFile, LeavesAFileNamedLikeTheOldTemporaryAlone) {
  ScratchDir dir;
  writePlain(dir.file("out.csv.tmp"), "mine");
  std::string why;
  ASSERT_TRUE(writeFileAtomically(dir.file("out.csv"), "new", why)) << why;
  EXPECT_EQ(readAll(dir.file("out.csv.tmp")), "mine");
  EXPECT_EQ(readAll(dir.file("out.csv")), "new");
}

TEST(AtomicFile, ReplacesASymlinkWithoutWritingItsTarget) {
  ScratchDir dir;
  writePlain(dir.file("target"), "precious");
  ASSERT_EQ(::symlink(dir.file("target").c_str(), dir.file("out.svg").c_str()), 0);
  std::string why;
  ASSERT_TRUE(writeFileAtomically(dir.file("out.svg"), "<svg/>", why)) << why;
  EXPECT_EQ(readAll(dir.file("target")), "precious");
  struct stat st {};
  ASSERT_EQ(::lstat(dir.file("out.svg").c_str(), &st), 0);
  EXPECT_TRUE(S_ISREG(st.st_mode));
  EXPECT_EQ(readAll(dir.file("out.svg")), "<svg/>");
}

TEST(AtomicFile, AMissingDirectoryFailsNamingTheFileAskedFor) {
  ScratchDir dir;
  const std::string path = dir.file("no/such/dir/out.csv");
  std::string why;
  EXPECT_FALSE(writeFileAtomically(path, "data", why));
  EXPECT_NE(why.find(path), std::string::npos) << why;
  EXPECT_NE(why.find("No such file or directory"), std::string::npos) << why;
  EXPECT_FALSE(canWriteFile(path, why));
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, ADirectoryOrNoNameIsRefused) {
  ScratchDir dir;
  std::string why;
  ASSERT_EQ(::mkdir(dir.file("sub").c_str(), 0755), 0);
  EXPECT_FALSE(canWriteFile(dir.file("sub"), why));
  EXPECT_NE(why.find("directory"), std::string::npos) << why;
  EXPECT_FALSE(writeFileAtomically(dir.file("sub") + "/", "x", why));
  EXPECT_FALSE(writeFileAtomically("", "x", why));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"sub"});
}

// Renaming over a device or a FIFO would replace it with a regular file (as root, /dev/null
// itself): such a name is refused before anything is written, by every writer.
TEST(AtomicFile, ADeviceAFifoOrASymlinkToOneIsRefusedAndLeftAlone) {
  ScratchDir dir;
  ASSERT_EQ(::mkfifo(dir.file("pipe").c_str(), 0600), 0);
  ASSERT_EQ(::symlink(dir.file("pipe").c_str(), dir.file("to-pipe").c_str()), 0);
  ASSERT_EQ(::mkdir(dir.file("sub").c_str(), 0755), 0);
  ASSERT_EQ(::symlink(dir.file("sub").c_str(), dir.file("to-sub").c_str()), 0);
  for (const std::string& name :
       {dir.file("pipe"), dir.file("to-pipe"), dir.file("to-sub"), std::string("/dev/null")}) {
    std::string why;
    EXPECT_FALSE(canWriteFile(name, why)) << name;
    EXPECT_NE(why.find(name), std::string::npos) << why;
    EXPECT_FALSE(writeFileAtomically(name, "data", why)) << name;
    EXPECT_NE(why.find("only a regular file"), std::string::npos) << why;
    bool wrote = false;
    EXPECT_FALSE(writeFileAtomicallyWith(
        name, ".png", [&](const std::string&) { return wrote = true; },
        [](const std::string&) { return true; }, why));
    EXPECT_FALSE(wrote) << name;
  }
  struct stat st {};
  ASSERT_EQ(::lstat(dir.file("pipe").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  ASSERT_EQ(::lstat(dir.file("to-pipe").c_str(), &st), 0);
  EXPECT_TRUE(S_ISLNK(st.st_mode));
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  ::rmdir(dir.file("sub").c_str());
}

TEST(AtomicFile, ADanglingSymlinkIsReplacedLikeANewName) {
  ScratchDir dir;
  ASSERT_EQ(::symlink(dir.file("nowhere").c_str(), dir.file("out.csv").c_str()), 0);
  std::string why;
  EXPECT_TRUE(canWriteFile(dir.file("out.csv"), why)) << why;
  ASSERT_TRUE(writeFileAtomically(dir.file("out.csv"), "a,b", why)) << why;
  struct stat st {};
  ASSERT_EQ(::lstat(dir.file("out.csv").c_str(), &st), 0);
  EXPECT_TRUE(S_ISREG(st.st_mode));
  EXPECT_EQ(readAll(dir.file("out.csv")), "a,b");
}

TEST(AtomicFile, AFullDiskLeavesNoFileAndNoTemporary) {
  // /dev/full stands in for a full disk for the writer; the directory must end up as it was.
  ScratchDir dir;
  std::string why;
  const auto copy_to_full = [](const std::string&) {
    std::ofstream full("/dev/full", std::ios::binary);
    full << std::string(1 << 16, 'x');
    return static_cast<bool>(full.flush());
  };
  EXPECT_FALSE(writeFileAtomicallyWith(
      dir.file("shot.png"), ".png", copy_to_full, [](const std::string&) { return true; }, why));
  EXPECT_NE(why.find(dir.file("shot.png")), std::string::npos) << why;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, AFileThatDoesNotReadBackWholeIsNotKept) {
  ScratchDir dir;
  std::string seen;
  std::string why;
  EXPECT_FALSE(writeFileAtomicallyWith(
      dir.file("shot.png"), ".png",
      [&seen](const std::string& tmp) {
        seen = tmp;
        writePlain(tmp, "trunc");
        return true;
      },
      [](const std::string&) { return false; }, why));
  EXPECT_EQ(seen.substr(seen.size() - 4), ".png");
  EXPECT_NE(why.find("not whole"), std::string::npos) << why;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicFile, AWrittenFileHasTheUsualPermissions) {
  ScratchDir dir;
  std::string why;
  ASSERT_TRUE(writeFileAtomically(dir.file("out.csv"), "a,b\n", why)) << why;
  struct stat st {};
  ASSERT_EQ(::stat(dir.file("out.csv").c_str(), &st), 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
}

}  // namespace
}  // namespace nineball
