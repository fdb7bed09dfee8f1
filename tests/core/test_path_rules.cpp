// paths::real_path and PathRules (issue 52 point 1): links on the final name
// and on parents, dangling links, ".." after a link, /proc.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>

#include "core/files.h"
#include "core/path_rules.h"

using namespace squawk;
namespace fs = std::filesystem;

TEST_CASE("real_path follows every link, dangling ones included, and applies .. after them") {
  const fs::path t = fs::temp_directory_path() / ("squawk_real_path_" + std::to_string(::getpid()));
  fs::remove_all(t);
  fs::create_directories(t / "in" / "sub");
  fs::create_directories(t / "out");
  fs::create_symlink(t / "out", t / "in" / "dir_link");
  fs::create_symlink(t / "out" / "not_yet", t / "in" / "dangling");
  fs::create_symlink("dangling", t / "in" / "chain");  // relative, to a dangling link
  fs::create_symlink(t / "in" / "loop", t / "in" / "loop");
  CHECK(*paths::real_path((t / "in" / "dir_link" / "f").string()) == (t / "out" / "f").string());
  CHECK(*paths::real_path((t / "in" / "dangling").string()) == (t / "out" / "not_yet").string());
  CHECK(*paths::real_path((t / "in" / "chain").string()) == (t / "out" / "not_yet").string());
  // ".." after a link climbs from the link's target, as the kernel does.
  CHECK(*paths::real_path((t / "in" / "dir_link" / ".." / "x").string()) == (t / "x").string());
  CHECK(*paths::real_path((t / "in" / "sub" / ".." / "y").string()) == (t / "in" / "y").string());
  CHECK(!paths::real_path((t / "in" / "loop").string()).is_ok());

  paths::PathRules rules;
  rules.allow_read((t / "in").string());
  rules.allow_write((t / "in").string());
  CHECK(rules.check_read((t / "in" / "sub" / "f").string(), "f").is_ok());
  for (const char* bad : {"dir_link/f", "dangling", "chain", "sub/../../out/f"}) {
    CAPTURE(bad);
    const Status r = rules.check_read((t / "in" / bad).string(), "f");
    CHECK(r.message().find("not allowed") != std::string::npos);
    CHECK(!rules.check_write((t / "in" / bad).string(), "f").is_ok());
  }
  CHECK(!rules.check_read_folder((t / "in").string(), "folder").is_ok());  // it holds links out
  fs::remove(t / "in" / "dir_link");
  fs::remove(t / "in" / "dangling");
  fs::remove(t / "in" / "chain");
  fs::remove(t / "in" / "loop");
  CHECK(rules.check_read_folder((t / "in").string(), "folder").is_ok());
  paths::PathRules root;
  root.allow_read("/");
  CHECK(root.check_read("/etc/hostname", "f").is_ok());
  CHECK(root.check_read("/proc/self/environ", "f").message().find("/proc") != std::string::npos);
  CHECK(!root.check_read("/proc/self/root/etc/hostname", "f").is_ok());
  CHECK(!root.check_read("/dev/stdin", "f").is_ok());
  CHECK(paths::PathRules::unrestricted().check_read("/proc/self/environ", "f").is_ok());
  fs::remove_all(t);
}

TEST_CASE("AtomicWriter: temp file beside the target, links followed, special files in place, errors kept") {
  const fs::path t = fs::temp_directory_path() / ("squawk_atomic_" + std::to_string(::getpid()));
  fs::remove_all(t);
  fs::create_directories(t / "real");
  const std::string target = (t / "real" / "f.txt").string();
  REQUIRE(files::write_atomic(target, "old"));
  // An uncommitted writer leaves the previous file and no temporary file.
  {
    auto w = files::AtomicWriter::open(target);
    REQUIRE(w);
    (*w)->out() << "half";
  }
  CHECK(*files::read(target) == "old");
  CHECK(std::distance(fs::directory_iterator(t / "real"), fs::directory_iterator()) == 1);
  // Through a link: the target is replaced, the link stays a link.
  fs::create_symlink(target, t / "link");
  REQUIRE(files::write_atomic((t / "link").string(), "new"));
  CHECK(fs::is_symlink(t / "link"));
  CHECK(*files::read(target) == "new");
  // A dangling link creates its target.
  fs::create_symlink(t / "real" / "later.txt", t / "dangling");
  REQUIRE(files::write_atomic((t / "dangling").string(), "x"));
  CHECK(fs::is_symlink(t / "dangling"));
  CHECK(*files::read((t / "real" / "later.txt").string()) == "x");
  // A folder is refused; a character device is written in place.
  CHECK(files::write_atomic((t / "real").string(), "x").message().find("a folder") != std::string::npos);
  CHECK(files::write_atomic("/dev/null", "x").is_ok());
  if (fs::exists("/dev/full")) {
    const Status full = files::write_atomic("/dev/full", std::string(1 << 16, 'x'));
    CHECK(full.message().find("No space left") != std::string::npos);
    CHECK(fs::is_character_file("/dev/full"));
  }
  fs::remove_all(t);
}
