// No Lua value reaches C++ unprotected: tables whose __index raises, error
// objects of every type and integer extremes each come back as a clean error
// message (no panic, no abort, no NULL string).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "script/advisory.h"
#include "script/prompt_renderer.h"
#include "script/scenario.h"
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
