// The Lua host: sandbox, require, errors with file:line, instruction cap,
// engine-seeded math.random, the assertion API.
#include <doctest/doctest.h>

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/rng.h"
#include "script/vm.h"
#include "scratch_dir.h"

using namespace squawk;
namespace fs = std::filesystem;

namespace {
fs::path scratch() { return test::scratch_dir("vm"); }
void write(const fs::path& p, const std::string& s) { std::ofstream(p) << s; }
}  // namespace

TEST_CASE("sandbox withholds os.execute, io.popen, loadlib, dofile with a hint") {
  script::Vm vm({});
  for (const char* code : {"os.execute('true')", "io.popen('ls')", "package.loadlib('x','y')",
                           "dofile('/etc/passwd')", "os.remove('x')"}) {
    Status st = vm.run_string(code, "t.lua");
    REQUIRE(!st.is_ok());
    CHECK(st.message().find("not allowed in the sandbox") != std::string::npos);
    CHECK(st.message().find("--unsafe") != std::string::npos);
  }
  // Binary chunks are refused by load.
  Status st = vm.run_string("local f = load(string.dump(function() end)); assert(f)", "t.lua");
  CHECK(!st.is_ok());
}

TEST_CASE("unsafe mode opens the standard library") {
  script::VmOptions o;
  o.unsafe = true;
  script::Vm vm(o);
  CHECK(vm.run_string("assert(type(os.execute) == 'function'); assert(io.popen)", "t.lua").is_ok());
}

TEST_CASE("writes only inside the output folder") {
  const fs::path d = scratch();
  script::VmOptions o;
  o.out_dir = (d / "out").string();
  fs::create_directories(o.out_dir);
  script::Vm vm(o);
  const std::string inside = (d / "out" / "a.txt").string();
  CHECK(vm.run_string("local f = assert(io.open('" + inside + "', 'w')); f:write('x'); f:close()", "t")
            .is_ok());
  CHECK(fs::exists(inside));
  Status st = vm.run_string("io.open('" + (d / "b.txt").string() + "', 'w')", "t");
  REQUIRE(!st.is_ok());
  CHECK(st.message().find("outside the output folder") != std::string::npos);
  script::Vm closed({});
  st = closed.run_string("io.open('" + inside + "', 'a')", "t");
  CHECK(st.message().find("--out DIR") != std::string::npos);
  st = closed.run_string("local f = assert(io.open('" + inside + "', 'r')); f:close()", "t");
  CHECK(st.message().find("--allow-read DIR") != std::string::npos);  // reads are sandboxed too
  script::VmOptions ro;
  ro.read_dirs = {d.string()};
  script::Vm reader(ro);
  CHECK(reader.run_string("local f = assert(io.open('" + inside + "', 'r')); f:close()", "t").is_ok());
}

TEST_CASE("require finds modules next to the script; errors carry file:line") {
  const fs::path d = scratch() / "req";
  fs::create_directories(d);
  write(d / "helper.lua", "local M = {}\n\n\n\n\n\nfunction M.fail() error('deliberate') end\nreturn M\n");
  write(d / "main.lua", "local h = require 'helper'\nh.fail()\n");
  script::Vm vm({});
  Status st = vm.run_file((d / "main.lua").string());
  REQUIRE(!st.is_ok());
  CHECK(st.message().find("helper.lua:7: deliberate") != std::string::npos);
  CHECK(st.message().find("stack traceback") != std::string::npos);
  CHECK(st.message().find("main.lua:2") != std::string::npos);
  // Modules outside the allowed folders are not found, with a clear message.
  st = vm.run_string("require 'no_such_module_xyz'", "t");
  CHECK(st.message().find("allowed folders") != std::string::npos);
}

TEST_CASE("instruction cap stops a runaway loop with a clear message") {
  script::VmOptions o;
  o.max_instructions = 1'000'000;
  script::Vm vm(o);
  Status st = vm.run_string("local x = 0\nwhile true do x = x + 1 end", "loop.lua");
  REQUIRE(!st.is_ok());
  CHECK(st.message().find("loop.lua:2:") != std::string::npos);
  CHECK(st.message().find("--max-instructions") != std::string::npos);
  // A pcall cannot swallow the stop.
  script::Vm vm2(o);
  st = vm2.run_string("while true do pcall(function() while true do end end) end", "p.lua");
  CHECK(!st.is_ok());
}

TEST_CASE("math.random draws from the engine RNG: same seed, same numbers") {
  for (uint64_t seed : {5u, 5u, 77u}) {
    script::VmOptions o;
    o.seed = seed;
    script::Vm vm(o);
    Rng ref(seed);
    char code[256];
    std::snprintf(code, sizeof code, "check_eq(math.random(), %.17g)", ref.uniform());
    REQUIRE(vm.run_string(code, "t").is_ok());
    std::snprintf(code, sizeof code, "check_eq(math.random(6), %lld)",
                  static_cast<long long>(ref.uniform_int(1, 6)));
    REQUIRE(vm.run_string(code, "t").is_ok());
    std::snprintf(code, sizeof code, "math.randomseed(3); check_eq(math.random(10, 20), %lld)",
                  static_cast<long long>(Rng(3).uniform_int(10, 20)));
    REQUIRE(vm.run_string(code, "t").is_ok());
    CHECK(vm.checks().passed == 3);
    CHECK(vm.checks().failed == 0);
  }
}

TEST_CASE("assertion API counts and reports") {
  script::Vm vm({});
  REQUIRE(vm.run_string("check(true); check_eq(1 + 1, 2); check_near(0.1 + 0.2, 0.3, 1e-12)", "t").is_ok());
  CHECK(vm.checks().passed == 3);
  CHECK(vm.checks().failed == 0);
  REQUIRE(vm.run_string("check(false, 'oops'); check_eq('a', 'b'); check_near(1, 2, 0.5)", "t").is_ok());
  CHECK(vm.checks().failed == 3);
  Status st = vm.run_string("check_near('x', 1, 1)", "t");
  CHECK(!st.is_ok());
  CHECK(st.message().find("expected number") != std::string::npos);
}

TEST_CASE("a link swapped in between the check and the open never leads out (io.open, io.lines, require)") {
  // inside/data.lua flips, by atomic renames from another thread, between a
  // file inside and a link to outside/secret.lua. Each open is checked by
  // name and again on the descriptor opened, and `require` loads from that
  // descriptor: no read may ever see the secret, whichever way the race goes.
  const fs::path root = scratch() / "swap";
  fs::remove_all(root);
  fs::create_directories(root / "inside");
  fs::create_directories(root / "outside");
  write(root / "outside" / "secret.lua", "return 'secret'\n");
  const std::string data = (root / "inside" / "data.lua").string();
  const std::string plain_tmp = (root / "inside" / "plain.tmp").string();
  const std::string link_tmp = (root / "inside" / "link.tmp").string();
  const std::string secret = (root / "outside" / "secret.lua").string();
  write(data, "return 'inside'\n");
  std::atomic<bool> stop{false};
  std::thread swapper([&] {
    while (!stop.load()) {
      if (::symlink(secret.c_str(), link_tmp.c_str()) == 0) std::rename(link_tmp.c_str(), data.c_str());
      write(plain_tmp, "return 'inside'\n");
      std::rename(plain_tmp.c_str(), data.c_str());
    }
  });
  script::VmOptions o;
  o.read_dirs = {(root / "inside").string()};
  o.require_dirs = {(root / "inside").string()};
  script::Vm vm(o);
  const Status st = vm.run_string("local P = [[" + data + "]]\n" + R"(
    local leaked, read, refused = 0, 0, 0
    local function seen(text)
      if text:find("secret", 1, true) then leaked = leaked + 1 else read = read + 1 end
    end
    -- at least 3000 rounds, and on until both sides of the race were seen (a starved swapper thread
    -- on a loaded machine can leave one side for a while), at most 300 000
    local n = 0
    while (n < 3000 or read == 0 or refused == 0) and n < 300000 do
      n = n + 1
      local ok, f = pcall(io.open, P)
      if ok and f then seen(f:read("a")) f:close() elseif not ok then refused = refused + 1 end
      local ok2, it = pcall(io.lines, P, "a")
      if ok2 then seen(it() or "") else refused = refused + 1 end
      package.loaded.data = nil
      local ok3, v = pcall(require, "data")
      if ok3 then seen(v) else refused = refused + 1 end
    end
    assert(leaked == 0, leaked .. " reads of the file outside")
    assert(read > 0 and refused > 0, "the swap never happened: " .. read .. " reads, " .. refused .. " refusals")
  )",
                                  "swap.lua");
  stop = true;
  swapper.join();
  CHECK_MESSAGE(st.is_ok(), st.message());
}

TEST_CASE("the Vm's memory limit holds over the pooled heap, and the Vm runs on after it") {
  script::VmOptions o;
  o.max_memory = 8LL << 20;
  script::Vm vm(o);
  // Many small tables and strings (the small classes) in one growing array (the system's blocks).
  const Status st = vm.run_string(
      "local keep = {} for i = 1, 1e7 do keep[#keep + 1] = {i, tostring(i)} end", "t.lua");
  REQUIRE(!st.is_ok());
  CHECK(st.message().find("Lua memory reached 8 MiB") != std::string::npos);
  CHECK(vm.run_string("collectgarbage(); local t = {} for i = 1, 1000 do t[i] = {i} end "
                      "assert(#t == 1000 and t[1000][1] == 1000)",
                      "t.lua")
            .is_ok());
}
