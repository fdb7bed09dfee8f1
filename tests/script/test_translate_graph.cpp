// C++ callers of the translation graph (script/translate_graph.h): one call,
// the traffic passed as a Stack (copied, never changed), and the dialogue.
#include <doctest/doctest.h>

#include "command/stack.h"
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
