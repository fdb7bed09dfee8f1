// Registration of the squawk Lua API: one bind_<area>() per bind_<area>.cpp.
#pragma once

struct lua_State;

namespace squawk::script {

void bind_core(lua_State* L);  // squawk.version/home/seed/out_dir, check*, math.random

// Registers every area's bindings (called once per Vm).
void bind_all(lua_State* L);

}  // namespace squawk::script
