// libFuzzer target: generated Lua scripts in the sandboxed VM with the squawk
// API. Each input byte pair picks a statement from a list of userdata-abusing,
// budget-testing and sandbox-probing templates (with a small number from the
// second byte). In input whose first byte is '!', a first byte of 252-255
// picks from the rare list instead: statements whose first use per VM loads
// the translation graph's Lua modules or builds a retrieval index (~7 ms in
// Release, ~30 ms under ASan); ungated, libFuzzer's comparison hints made
// them appear in most inputs and take over half of all fuzzing time. Input
// starting with '#' runs the rest as raw Lua instead.
// Invariants: no crash, no sanitizer report, no hang (a small instruction
// budget per call); errors are Status values.
#include <cstddef>
#include <cstdint>
#include <string>

#include "script/vm.h"

using namespace squawk;

namespace {

const char* const kStatements[] = {
    "local s = squawk.sim.new{} ; X[#X + 1] = s",
    "X[#X + 1] = squawk.sim.new{seed = %d}",
    "X[#X] = nil",
    "X = {}",
    "collectgarbage()",
    "collectgarbage('step', %d)",
    "local o = X[#X] if o then o:exec('CRE KL%d B738 52 4 90 FL200 250') end",
    "local o = X[#X] if o then o:step(%d) end",
    "local o = X[#X] if o then o:run_for(%d) end",
    "local o = X[#X] if o then o:exec('SCHEDULE 00:00:0%d ECHO x') end",
    "local o = X[#X] if o then o:exec('DT 0.0%d') end",
    "local o = X[#X] if o then X[#X + 1] = o:copy() end",
    "local o = X[#X] if o then o:aircraft() o:conflicts() o:snapshot() o:output() end",
    "setmetatable({ x = X[#X] }, { __gc = function(t) R = t.x end })",
    "if R then R:exec('CRE KL1 B738 52 4 90 FL200 250') end",
    "if R then R:count() end",
    "local m = getmetatable(X[#X] or 0) if type(m) == 'table' and m.__gc then m.__gc(X[1]) end",
    "local o = X[#X] if o then o.exec(X[1], 'ECHO x') end",
    "local o = X[#X] if o then o.count({}) end",
    "local c = coroutine.wrap(function() for i = 1, %d * 100 do end coroutine.yield() end) c()",
    "for i = 1, %d do coroutine.resume(coroutine.create(function() end)) end",
    "while true do end",
    "string.rep('x', %d * 1000)",
    "io.open('/etc/passwd')",
    "io.lines('/proc/self/environ')",
    "os.getenv('SQUAWK_LLM_API_KEY')",
    "io.open('x%d.txt', 'w')",
    "squawk.llm.client{ url = 'http://127.0.0.1:1', model = 'm', timeout = %d / 0 }",
    "squawk.env.evaluate{ scenario = 'scenarios/horizontal_cr.lua', episodes = %d / 0 }",
    "local t = {} for i = 1, %d do t[i] = {} end",
    "error('boom %d')",
    "local o = X[#X] if o then o:search('climb %d', 3) end",
};
constexpr size_t kCount = sizeof(kStatements) / sizeof(kStatements[0]);

const char* const kRare[] = {
    "local o = X[#X] if o then squawk.translate.run('KL%d climb FL300', { sim = o, mode = 'offline' }) end",
    "squawk.translate.run('climb FL%d', { mode = 'offline' })",
    "RI = RI or squawk.rag.index{} X[#X + 1] = RI",  // one index per input: building it is ~1 ms
};
constexpr size_t kRareCount = sizeof(kRare) / sizeof(kRare[0]);
constexpr uint8_t kRareFrom = 252;

std::string generate(const uint8_t* data, size_t size) {
  std::string code = "X = {}\n";
  const bool rare_allowed = size > 0 && data[0] == '!';
  for (size_t i = 0; i + 1 < size; i += 2) {
    const bool rare = rare_allowed && data[i] >= kRareFrom;
    std::string st = rare ? kRare[data[i + 1] % kRareCount] : kStatements[data[i] % kCount];
    const auto at = st.find("%d");
    const int n = rare ? data[i + 1] / kRareCount % 64 : data[i + 1] % 64;
    if (at != std::string::npos) st.replace(at, 2, std::to_string(n));
    code += "pcall(function() " + st + " end)\n";
  }
  return code;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  script::VmOptions o;
  o.max_instructions = 200'000;
  const bool raw = size > 0 && data[0] == '#';
  const std::string code =
      raw ? std::string(reinterpret_cast<const char*>(data + 1), size - 1) : generate(data, size);
  {
    script::Vm vm(o);
    (void)vm.run_string(code, "fuzz");
    (void)vm.run_string("collectgarbage() if R then pcall(R.count, R) end", "after");
  }
  return 0;
}
