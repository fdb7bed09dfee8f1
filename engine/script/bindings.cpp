#include "script/bindings.h"

namespace squawk::script {

void bind_all(lua_State* L) { bind_core(L); }

}  // namespace squawk::script
