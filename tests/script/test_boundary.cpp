// No Lua value reaches C++ unprotected: tables whose __index raises, error
// objects of every type and integer extremes each come back as a clean error
// message (no panic, no abort, no NULL string).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "script/advisory.h"
#include "script/prompt_renderer.h"
#include "script/repl_session.h"
#include "script/scenario.h"
#include "script/serve_session.h"
#include "script/vm.h"
#include "scratch_dir.h"

using namespace squawk;
namespace fs = std::filesystem;

namespace {

fs::path scratch() { return test::scratch_dir("boundary"); }

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return p.string();
}

// A table whose every field read raises `raise` (a Lua expression).
std::string raising_table(const std::string& raise) {
  return "return setmetatable({}, {__index = function() error(" + raise + ") end})\n";
}

// The error objects a script can raise: string, table, nil, a number, a
// userdata-like table whose __tostring raises, one whose __tostring returns a table.
const char* const kErrors[] = {"'boom'", "{}", "nil", "42",
                               "setmetatable({}, {__tostring = function() error('again') end})",
                               "setmetatable({}, {__tostring = function() return {} end})"};

script::Advisory advisory() {
  script::Advisory a;
  a.callsign = "KL1";
  a.turn = "left";
  return a;
}

// Makes `module` resolve to tests/hardening/<file> in `vm` (package.preload
// is searched before the shipped scripts/).
void preload(script::Vm& vm, const std::string& module, const std::string& file) {
  std::ifstream in(std::string(SQUAWK_SOURCE_DIR) + "/tests/hardening/" + file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(!text.empty());
  const Status st =
      vm.run_string("package.preload['" + module + "'] = function(...)\n" + text + "\nend", "preload");
  REQUIRE_MESSAGE(st.is_ok(), st.message());
}

}  // namespace

TEST_CASE("a scenario, prompt template or advisory table whose __index raises is a clean error") {
  for (const char* e : kErrors) {
    CAPTURE(e);
    auto sc = script::load_scenario(write("raising_scenario.lua", raising_table(e)), {});
    REQUIRE(!sc.is_ok());
    CHECK(sc.status().message().find("reading field") != std::string::npos);
    auto pr = script::PromptRenderer::load(write("raising_prompt.lua", raising_table(e)), {});
    REQUIRE(!pr.is_ok());
    CHECK(pr.status().message().find("reading field 'prefix'") != std::string::npos);
    auto ad = script::AdvisoryPhraser::load(write("raising_advisory.lua", raising_table(e)), {});
    REQUIRE(!ad.is_ok());
    CHECK(ad.status().message().find("reading field 'advise'") != std::string::npos);
  }
}

TEST_CASE("advise() raising any error object is a clean error message") {
  for (const char* e : kErrors) {
    CAPTURE(e);
    auto ad = script::AdvisoryPhraser::load(
        write("advisory_raises.lua", std::string("return {advise = function(d) error(") + e + ") end}\n"), {});
    REQUIRE(ad.is_ok());
    auto r = ad->phrase(advisory());
    REQUIRE(!r.is_ok());
    CHECK(r.status().message().rfind("advise(): ", 0) == 0);
  }
  // The module table's own __index raising when advise is looked up per call.
  auto ad = script::AdvisoryPhraser::load(
      write("advisory_late.lua",
            "local n = 0\n"
            "return setmetatable({}, {__index = function(t, k) n = n + 1\n"
            "  if n > 1 then error({}) end return function() return 'ok' end end})\n"),
      {});
  REQUIRE(ad.is_ok());
  auto r = ad->phrase(advisory());
  REQUIRE(!r.is_ok());
  CHECK(r.status().message().find("error object is a table value") != std::string::npos);
}

TEST_CASE("option tables whose __index or __len raise reach the bindings as Lua errors") {
  script::Vm vm({});
  const char* code = R"(
    local raising = setmetatable({}, {__index = function() error({}) end,
                                      __len = function() error(nil) end})
    for _, f in ipairs({
      function() return squawk.sim.new(raising) end,
      function() return squawk.env.evaluate(raising) end,
      function() return squawk.rag.index(raising) end,
      function() return squawk.llm.client(raising) end,
    }) do
      local ok, e = pcall(f)
      assert(not ok, "accepted a raising table")
      assert(type(e) == "string", "error is a " .. type(e))
    end
    -- check() shows a value whose __tostring raises without crashing.
    local bad = setmetatable({}, {__tostring = function() error({}) end})
    local ok = pcall(check_eq, bad, 1)
    assert(not ok)
    -- check_eq's == runs __eq under a protected call.
    local mt = {__eq = function() error({}) end}
    local ok2, e2 = pcall(check_eq, setmetatable({}, mt), setmetatable({}, mt))
    assert(not ok2 and type(e2) == "string" and e2:find("comparing with ==", 1, true), tostring(e2))
  )";
  const Status st = vm.run_string(code, "raising.lua");
  CHECK_MESSAGE(st.is_ok(), st.message());
}

TEST_CASE("math.random over the whole integer range stays in range (no overflow)") {
  script::Vm vm({});
  const Status st = vm.run_string(R"(
    for _ = 1, 1000 do
      local v = math.random(math.mininteger, math.maxinteger)
      assert(math.type(v) == "integer")
      local w = math.random(math.mininteger, -1)
      assert(w < 0, w)
      local x = math.random(0, math.maxinteger)
      assert(x >= 0, x)
    end
    assert(math.random(math.maxinteger, math.maxinteger) == math.maxinteger)
    assert(math.random(math.mininteger, math.mininteger) == math.mininteger)
  )", "random.lua");
  CHECK_MESSAGE(st.is_ok(), st.message());
}

TEST_CASE("the REPL and serve sessions read the session module's tables under protected calls") {
  script::Vm repl_vm({});
  preload(repl_vm, "translate.repl", "hostile_repl_module.lua");
  auto bad_module = script::ReplSession::open(repl_vm, "", "");
  REQUIRE(!bad_module.is_ok());
  CHECK(bad_module.status().message() ==
        "translate.repl.new: reading field 'new': (error object is a table value)");

  script::Vm vm({});
  preload(vm, "translate.repl", "hostile_repl_session.lua");
  auto repl = script::ReplSession::open(vm, "", "");
  REQUIRE_MESSAGE(repl.is_ok(), repl.status().message());
  CHECK(*repl->opening() == "hostile session");
  for (const char* method : {"handle", "tick", "complete", "banner"}) {
    CAPTURE(method);
    const Status st = std::string(method) == "handle"   ? repl->handle("hi").status()
                      : std::string(method) == "tick"   ? repl->tick(1.0).status()
                      : std::string(method) == "banner" ? repl->banner().status()
                                                        : repl->complete("K").status();
    CHECK(st.message() == std::string("translate.repl session:") + method + ": reading field '" + method +
                              "': (error object is a table value)");
  }

  script::Vm serve_vm({});
  preload(serve_vm, "translate.session", "hostile_serve_session.lua");
  auto serve = script::ServeSession::open(serve_vm, "", "");
  REQUIRE_MESSAGE(serve.is_ok(), serve.status().message());
  auto fine = (*serve)->command("fine", {});
  REQUIRE_MESSAGE(fine.is_ok(), fine.status().message());
  CHECK(fine->ok);
  for (const char* text : {"reply", "commands", "results", "events"}) {
    CAPTURE(text);
    auto r = (*serve)->command(text, {});
    REQUIRE(!r.is_ok());
    CHECK(r.status().message().rfind("translate.session command()'s reply: ", 0) == 0);
    CHECK(r.status().message().find("(error object is a") != std::string::npos);
  }
  auto events = (*serve)->tick(1.0);
  REQUIRE(!events.is_ok());
  CHECK(events.status().message() == "translate.session tick()'s events: reading the length: 42");
  CHECK((*serve)->command("fine", {}).is_ok());  // the session stays usable
}
