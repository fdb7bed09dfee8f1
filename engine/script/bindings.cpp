#include "script/bindings.h"

namespace squawk::script {

void bind_all(lua_State* L) {
  bind_core(L);
  bind_env(L);
  bind_gpt2(L);
  bind_llm(L);
  bind_rag(L);
  bind_translate(L);
  bind_sim(L);
  bind_geo(L);
  bind_gym(L);
  bind_rl(L);
}

}  // namespace squawk::script
