// paths::real_path and PathRules (issue 52 point 1): links on the final name
// and on parents, dangling links, ".." after a link, /proc.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>

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
