// C++ callers of the translation graph (script/translate_graph.h): one call,
// the traffic passed as a Stack (copied, never changed), and the dialogue.
#include <doctest/doctest.h>

#include <lua.hpp>

#include "command/stack.h"
#include "script/repl_session.h"
#include "script/translate_graph.h"
#include "translate/stack_world.h"

using namespace squawk;

TEST_CASE("run_translation_graph: commands against a Stack's traffic, which stays untouched") {
  script::Vm vm({});
  command::Stack stack;
  REQUIRE(translate::setup_stack(stack, "CRE KL204 A320 52 4 90 FL250 280").is_ok());
  const std::string before = stack.snapshot();
  auto tr = script::run_translation_graph(vm, "KL204 turn left 20 degrees", {"offline", "", &stack});
  REQUIRE_MESSAGE(tr.is_ok(), tr.status().message());
  CHECK(tr->issued());
  CHECK(tr->text() == "HDG KL204 70 LEFT");
  CHECK(stack.snapshot() == before);
  auto setup = script::run_translation_graph(vm, "KL204 descend", {"offline", "CRE KL204 A320 52 4 90 FL250 280"});
  REQUIRE(setup.is_ok());
  CHECK(setup->asked());
  CHECK(setup->ask.find("altitude") != std::string::npos);
}

TEST_CASE(
    "collect_after_reply: one step owed per request, taken once; a request finding one owed takes "
    "it itself") {
  script::Vm vm({});
  command::Stack stack;
  REQUIRE(translate::setup_stack(stack, "CRE KL204 A320 52 4 90 FL250 280").is_ok());
  CHECK(script::collect_after_reply(vm).freed_kb == 0.0);  // (nothing asked yet: nothing owed)
  REQUIRE(script::run_translation_graph(vm, "KL204 turn left 20 degrees", {"offline", "", &stack})
              .is_ok());
  CHECK(script::collect_after_reply(vm).freed_kb > 0.0);  // (the request's garbage)
  const auto again = script::collect_after_reply(vm);
  CHECK(again.ms == 0.0);
  CHECK(again.freed_kb == 0.0);
  // (two requests with no step between: the second takes the first's, the translation the same)
  REQUIRE(script::run_translation_graph(vm, "KL204 turn left 20 degrees", {"offline", "", &stack})
              .is_ok());
  auto tr =
      script::run_translation_graph(vm, "KL204 turn left 20 degrees", {"offline", "", &stack});
  REQUIRE(tr.is_ok());
  CHECK(tr->text() == "HDG KL204 70 LEFT");
  CHECK(script::collect_after_reply(vm).freed_kb > 0.0);
}

TEST_CASE(
    "RequestCollection: the collector runs again after a request that returns, asks or fails; a "
    "stopped collector and an enclosing request are left alone") {
  script::Vm vm({});
  lua_State* L = vm.state();
  command::Stack stack;
  REQUIRE(translate::setup_stack(stack, "CRE KL204 A320 52 4 90 FL250 280").is_ok());
  auto tr = script::run_translation_graph(vm, "KL204 descend", {"offline", "", &stack});
  REQUIRE(tr.is_ok());
  CHECK(tr->asked());
  CHECK(lua_gc(L, LUA_GCISRUNNING) == 1);
  CHECK(vm.collection_owed());
  (void)script::collect_after_reply(vm);
  CHECK_FALSE(vm.collection_owed());

  // squawk.translate.request: fn's results; fn's error raised again with the collector running.
  const Status st = vm.run_string(R"(
    local a, b = squawk.translate.request(function(x, y)
      assert(not collectgarbage("isrunning"), "stopped inside the request")
      return x + y, "two"
    end, 1, 2)
    assert(a == 3 and b == "two")
    assert(collectgarbage("isrunning"))
    local ok, err = pcall(squawk.translate.request, function() error("no luck", 0) end)
    assert(not ok and err == "no luck", tostring(err))
    assert(collectgarbage("isrunning"), "running again after an error")
    local ok2, err2 = pcall(squawk.translate.request, function() error({}) end)
    assert(not ok2 and type(err2) == "table")
    assert(collectgarbage("isrunning"))
    assert(not pcall(squawk.translate.request, "not a function"))
  )",
                                  "request.lua");
  REQUIRE_MESSAGE(st.is_ok(), st.message());
  CHECK(lua_gc(L, LUA_GCISRUNNING) == 1);
  CHECK(vm.collection_owed());
  (void)script::collect_after_reply(vm);
  CHECK_FALSE(vm.collection_owed());

  // A request inside a request is one request: the inner scope neither steps nor restarts.
  {
    const script::RequestCollection outer(vm);
    CHECK(lua_gc(L, LUA_GCISRUNNING) == 0);
    {
      const script::RequestCollection inner(vm);
      CHECK(lua_gc(L, LUA_GCISRUNNING) == 0);
    }
    CHECK(lua_gc(L, LUA_GCISRUNNING) == 0);
  }
  CHECK(lua_gc(L, LUA_GCISRUNNING) == 1);
  (void)script::collect_after_reply(vm);

  // A collector a script stopped stays stopped, and no step is owed for it.
  lua_gc(L, LUA_GCSTOP);
  REQUIRE(script::run_translation_graph(vm, "KL204 turn left 20 degrees", {"offline", "", &stack})
              .is_ok());
  CHECK(lua_gc(L, LUA_GCISRUNNING) == 0);
  CHECK_FALSE(vm.collection_owed());
  lua_gc(L, LUA_GCRESTART);
}

namespace {

// Lua calls seen with the collector running and stopped (a call hook).
struct CallsSeen {
  long running = 0;
  long stopped = 0;
};
CallsSeen g_seen;

void count_call(lua_State* L, lua_Debug*) {
  ++(lua_gc(L, LUA_GCISRUNNING) == 0 ? g_seen.stopped : g_seen.running);
}

// The calls a REPL line makes, by the collector's mode.
CallsSeen calls_of(script::ReplSession& repl, const std::string& line,
                   std::string* text = nullptr) {
  g_seen = {};
  auto r = repl.handle(line);
  REQUIRE_MESSAGE(r.is_ok(), r.status().message());
  if (text) *text = r->text;
  return g_seen;
}

}  // namespace

TEST_CASE(
    "ReplSession: an English line is translated with the collector stopped and owes one step; "
    "TrafScript and :run run with it in its normal mode") {
  script::VmOptions o;
  o.max_instructions = 0;  // (no count hook: the test's call hook stands alone)
  script::Vm vm(o);
  lua_State* L = vm.state();
  auto repl = script::ReplSession::open(vm, "", "offline");
  REQUIRE_MESSAGE(repl.is_ok(), repl.status().message());
  lua_sethook(L, count_call, LUA_MASKCALL, 0);

  CallsSeen c = calls_of(*repl, "!CRE KL204 A320 52 4 90 FL250 280");
  CHECK(c.running > 0);
  CHECK(c.stopped == 0);
  CHECK_FALSE(vm.collection_owed());

  std::string text;
  c = calls_of(*repl, "KL204 turn left heading 020", &text);
  CHECK(text.find("> HDG KL204") != std::string::npos);
  CHECK(c.stopped > 0);  // (the translation)
  CHECK(c.running > 0);  // (the command it gave, and the reply's formatting)
  CHECK(lua_gc(L, LUA_GCISRUNNING) == 1);
  CHECK(vm.collection_owed());
  repl->collect_after_reply();
  CHECK_FALSE(vm.collection_owed());
  CHECK(script::collect_after_reply(vm).ms == 0.0);  // (taken once)

  c = calls_of(*repl, "KL204 descend", &text);  // asked
  CHECK(text.rfind("? ", 0) == 0);
  CHECK(c.stopped > 0);
  CHECK(lua_gc(L, LUA_GCISRUNNING) == 1);
  CHECK(vm.collection_owed());
  c = calls_of(*repl, "cancel");
  CHECK(lua_gc(L, LUA_GCISRUNNING) == 1);
  repl->collect_after_reply();

  c = calls_of(*repl, ":run 10", &text);
  CHECK(text.find("KL204") != std::string::npos);
  CHECK(c.running > 0);
  CHECK(c.stopped == 0);
  CHECK_FALSE(vm.collection_owed());
  lua_sethook(L, nullptr, 0, 0);
}

TEST_CASE("GraphDialogue: a question keeps its request, the answer completes it, cancel drops it") {
  script::Vm vm({});
  command::Stack stack;
  REQUIRE(translate::setup_stack(stack, "CRE KL204 A320 52 4 90 FL250 280 ; CRE AC02 A320 52 5 90 FL250 280").is_ok());
  auto d = script::GraphDialogue::open(vm, {"offline", "", &stack});
  REQUIRE_MESSAGE(d.is_ok(), d.status().message());
  auto q = d->say("KL204 descend");
  REQUIRE(q.is_ok());
  CHECK(q->asked());
  auto a = d->say("flight level 100");
  REQUIRE(a.is_ok());
  CHECK(a->text() == "ALT KL204 FL100");
  CHECK(d->say("AC02 turn left")->asked());
  auto c = d->say("cancel");
  REQUIRE(c.is_ok());
  CHECK(c->commands.empty());
  CHECK_FALSE(c->asked());
  CHECK(d->say("flight level 100")->asked());  // nothing pending: two aircraft, which one?
}
