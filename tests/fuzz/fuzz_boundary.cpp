// libFuzzer target (issue 52 point 6): Lua tables with hostile metatables fed
// to every C++ entry that reads a script table. Each input byte triple picks
// an entry, a hostile value and an error object. Hostile values: __index or
// __len raising an error object of any type, __index looping, yielding,
// collecting garbage or returning other hostile tables, arrays and nested
// option tables of them. Invariants: no crash, no sanitizer report, no hang
// (a small instruction budget per call); every failure is a Lua error string.
// (client:chat/embed read their tables the same way but reach the network,
// so they are left to tests/lua/hardening_messages.lua.)
#include <cstddef>
#include <cstdint>
#include <string>

#include "script/vm.h"

using namespace squawk;

namespace {

const char* const kPrelude = R"(
local errors = { 'boom', {}, false, 42, setmetatable({}, {__tostring = function() error('again') end}),
                 setmetatable({}, {__tostring = function() return {} end}), coroutine.create(function() end) }
local function E(k) return errors[k % #errors + 1] end
local function raising(k) return setmetatable({}, {__index = function() error(E(k)) end}) end
local H = {
  function(k) return raising(k) end,
  function(k) return setmetatable({1, 2, 3}, {__len = function() error(E(k)) end, __index = function() return 1 end}) end,
  function(k) return setmetatable({}, {__index = function() while true do end end}) end,
  function(k) return setmetatable({}, {__index = function() coroutine.yield(1) end}) end,
  function(k) return setmetatable({}, {__index = function() collectgarbage() return raising(k) end}) end,
  function(k) return setmetatable({}, {__index = function(_, key) return ({0/0, 1e308, -1, math.mininteger, '', {}, raising(k)})[k % 7 + 1] end}) end,
  function(k) return { raising(k), raising(k + 1), n = raising(k) } end,
  function(k) return { docs = { raising(k) }, messages = { raising(k) }, names = raising(k), seed = raising(k),
                       navdata = raising(k), scenario = raising(k), url = raising(k), model = raising(k) } end,
  function(k) return setmetatable({}, {__len = function() return 1e300 end, __index = function() return raising(k) end}) end,
  function(k) return setmetatable({}, {__len = function() return math.maxinteger end}) end,
}
local function V(h, k) return H[h % #H + 1](k) end
local sim = squawk.sim.new{}
local entries = {
  function(t, u) return squawk.sim.new(t) end,
  function(t, u) return squawk.env.evaluate(t) end,
  function(t, u) return squawk.rag.index(t) end,
  function(t, u) return squawk.llm.client(t) end,
  function(t, u) return squawk.translate.tables(t, u) end,
  function(t, u) return squawk.translate.utterance('KL1 climb FL300', t, u) end,
  function(t, u) return squawk.translate.best_match('klm', t) end,
  function(t, u) return squawk.translate.score(t, u, t) end,
  function(t, u) return squawk.translate.run('climb FL300', t) end,
  function(t, u) return check_eq(t, u) end,
  function(t, u) return check(t, u) end,
  function(t, u) return sim:exec(t) end,
  function(t, u) return tostring(t) .. #t end,
  function(t, u) return math.random(t, u) end,
  function(t, u) return squawk.env.new(t) end,
}
)";

std::string generate(const uint8_t* data, size_t size) {
  std::string code = kPrelude;
  for (size_t i = 0; i + 2 < size; i += 3) {
    const int entry = data[i], hostile = data[i + 1], err = data[i + 2];
    code += "pcall(entries[" + std::to_string(entry) + " % #entries + 1], V(" + std::to_string(hostile) + ", " +
            std::to_string(err) + "), V(" + std::to_string(hostile / 16) + ", " + std::to_string(err + 1) + "))\n";
  }
  return code;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  script::VmOptions o;
  o.max_instructions = 200'000;
  o.max_memory = 64LL << 20;
  script::Vm vm(o);
  (void)vm.run_string(generate(data, size), "boundary");
  return 0;
}
