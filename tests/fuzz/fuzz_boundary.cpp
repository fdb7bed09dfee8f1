// libFuzzer target (issue 52 point 6): Lua tables with hostile metatables fed
// to every C++ entry that reads a script table. Each input byte triple picks
// an entry, a hostile value and an error object. Hostile values: __index or
// __len raising an error object of any type, __index looping, yielding,
// collecting garbage or returning other hostile tables, arrays and nested
// option tables of them. Invariants: no crash, no sanitizer report, no hang
// (a small instruction budget per triple); every failure is a Lua error string.
// (client:chat/embed read their tables the same way but reach the network,
// so they are left to tests/lua/hardening_messages.lua.)
//
// Speed: one VM serves every input (the prelude, the translation graph and
// the simulator are built once). Each triple is its own call into the VM,
// with a fresh instruction budget; after each input what an input can change
// is put back: the simulator (re-created when sim:exec ran), the check
// counters and the random generator. Inputs past kMaxTriples are cut.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
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
-- squawk.rag.index reads `notes` and `docs`, then indexes the whole command
-- registry (no boundary code; it took a third of the run): through this
-- proxy `docs` gets one more entry, not a table, so the call fails after
-- every read of t.
local function no_build(t)
  return setmetatable({}, {__index = function(_, k)
    local v = t[k]
    if k ~= 'docs' or (v ~= nil and type(v) ~= 'table') then return v end
    local n = v and #v or 0
    return setmetatable({}, {__len = function() return n + 1 end,
                             __index = function(_, i) if i <= n then return v[i] end return 0 end})
  end})
end
local sim, sim_used = squawk.sim.new{}, false
local entries = {
  function(t, u) return squawk.sim.new(t) end,
  function(t, u) return squawk.env.evaluate(t) end,
  function(t, u) return squawk.rag.index(no_build(t)) end,
  function(t, u) return squawk.llm.client(t) end,
  function(t, u) return squawk.translate.tables(t, u) end,
  function(t, u) return squawk.translate.utterance('KL1 climb FL300', t, u) end,
  function(t, u) return squawk.translate.best_match('klm', t) end,
  function(t, u) return squawk.translate.score(t, u, t) end,
  function(t, u) return squawk.translate.run('climb FL300', t) end,
  function(t, u) return check_eq(t, u) end,
  function(t, u) return check(t, u) end,
  function(t, u) sim_used = true return sim:exec(t) end,
  function(t, u) return tostring(t) .. #t end,
  function(t, u) return math.random(t, u) end,
  function(t, u) return squawk.env.new(t) end,
}
-- One triple: entry `e` called with two hostile values.
function step(e, h, k) pcall(entries[e % #entries + 1], V(h, k), V(h // 16, k + 1)) end
-- Puts back what a step may change in the VM's globals.
function reset()
  if sim_used then sim, sim_used = squawk.sim.new{}, false end
end
)";

// Triples read per input (the rest is ignored): bounds an input's cost
// (a looping value spends a whole 200 000-instruction budget) however long
// the replay driver's mutants grow; libFuzzer runs use -max_len=48.
constexpr size_t kMaxTriples = 16;

script::Vm& vm() {
  static script::Vm* const v = [] {
    script::VmOptions o;
    o.max_instructions = 200'000;
    o.max_memory = 64LL << 20;
    auto* made = new script::Vm(o);  // lives for the whole run
    const Status st = made->run_string(kPrelude, "boundary prelude");
    if (!st.is_ok()) {
      std::fprintf(stderr, "fuzz_boundary: prelude failed: %s\n", st.message().c_str());
      std::abort();
    }
    return made;
  }();
  return *v;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  script::Vm& v = vm();
  size = std::min(size, kMaxTriples * 3);
  for (size_t i = 0; i + 2 < size; i += 3) {
    (void)v.run_string("step(" + std::to_string(data[i]) + ", " + std::to_string(data[i + 1]) + ", " +
                           std::to_string(data[i + 2]) + ")",
                       "boundary");
  }
  const Status st = v.run_string("reset()", "boundary reset");
  if (!st.is_ok()) {
    std::fprintf(stderr, "fuzz_boundary: reset failed: %s\n", st.message().c_str());
    std::abort();
  }
  v.checks() = {};
  v.rng().reseed(0);
  return 0;
}
