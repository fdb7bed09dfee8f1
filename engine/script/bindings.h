// Registration of the squawk Lua API: one bind_<area>() per bind_<area>.cpp.
#pragma once

#include <string>

#include "script/scenario.h"

struct lua_State;

namespace squawk::script {

void bind_core(lua_State* L);  // squawk.version/home/seed/out_dir, check*, math.random
void bind_gpt2(lua_State* L);  // squawk.gpt2 (GPT-2 model and tokenizer)
void bind_env(lua_State* L);   // squawk.env (conflict-resolution environment, evaluate)
void bind_llm(lua_State* L);   // squawk.llm (LLM clients), squawk.load_config
void bind_rag(lua_State* L);   // squawk.rag (BM25 over the command docs)
void bind_translate(lua_State* L);  // squawk.translate (offline translator, corpus scorer)
void bind_sim(lua_State* L);   // squawk.sim (simulation driven by TrafScript)
void bind_gym(lua_State* L);   // squawk.gym (environments written in Lua: load)
void bind_geo(lua_State* L);   // squawk.geo (geometry kernels: kwik*, CPA, polygons)
void bind_rl(lua_State* L);    // squawk.rl (train, evaluate: the CLI's learner and evaluator)

// Shared by bind_env.cpp and bind_rl.cpp: the scenario at `path` (already
// through the read check) or an ArgError; the body of squawk.env.evaluate,
// also squawk.rl.evaluate (register it through guarded<>).
Scenario scenario_or_throw(lua_State* L, const std::string& path);
int env_evaluate(lua_State* L);

// Registers every area's bindings (called once per Vm).
void bind_all(lua_State* L);

}  // namespace squawk::script
