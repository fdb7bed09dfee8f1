// squawk.llm: LLM clients from Lua; squawk.load_config: Lua data files.
//
//   squawk.llm.client{url=, model=, api="ollama"|"openai", temperature=, seed=,
//                     context=, max_tokens=, timeout=, connect_timeout=,
//                     retries=, backoff=}
//       A client. Unset fields come from SQUAWK_LLM_URL / SQUAWK_LLM_MODEL /
//       SQUAWK_LLM_API when set, else the LlmConfig defaults; the API is
//       inferred from the URL when not given. Raises on an invalid config.
//   squawk.llm.from_env()      -> client, or nil and the reason
//   client:chat(prompt | {{role=, content=}, ...}, [{system=, schema=, grammar=, on_token=fn}])
//       -> text, info{model, attempts, prompt_tokens, completion_tokens, finish_reason}
//       or nil, message when the server failed (the message names server,
//       model and what happened). schema is a Lua table or a JSON string.
//       on_token(fragment) turns streaming on.
//   client:embed({text, ...}) -> {{x, ...}, ...} or nil, message
//   client:describe()         -> "ollama server URL (model M)"
//
//   squawk.load_config(path) -> the table that the Lua file at `path` returns.
//       A relative path is resolved against squawk.home. The file runs in an
//       environment holding only string, table, math, utf8, pairs, ipairs,
//       select, type, tostring, tonumber and error; prompts/*.lua are loaded
//       this way, since prompts/ is not on the require path.
#include <memory>

#include <nlohmann/json.hpp>

#include "core/files.h"
#include "core/paths.h"
#include "llm/client.h"
#include "script/bindings.h"
#include "script/lua_util.h"

namespace squawk::script {

namespace {

constexpr const char* kClientMt = "squawk.llm.Client";
constexpr int kMaxJsonDepth = 64;

struct ClientBox {
  std::unique_ptr<llm::LlmClient> client;
};

// A Lua value as JSON: tables with keys 1..n become arrays, others objects.
nlohmann::json to_json(lua_State* L, int idx, int depth) {
  if (depth > kMaxJsonDepth) throw ArgError("schema: nested deeper than 64 levels (a cycle?)");
  idx = lua_absindex(L, idx);
  switch (lua_type(L, idx)) {
    case LUA_TNIL: return nullptr;
    case LUA_TBOOLEAN: return lua_toboolean(L, idx) != 0;
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) return static_cast<long long>(lua_tointeger(L, idx));
      return lua_tonumber(L, idx);
    case LUA_TSTRING: return std::string(lua_tostring(L, idx));
    case LUA_TTABLE: {
      const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
      size_t keys = 0;
      lua_pushnil(L);
      while (lua_next(L, idx)) {
        ++keys;
        lua_pop(L, 1);
      }
      if (n > 0 && static_cast<size_t>(n) == keys) {
        nlohmann::json arr = nlohmann::json::array();
        for (lua_Integer i = 1; i <= n; ++i) {
          get_index(L, idx, i);
          arr.push_back(to_json(L, -1, depth + 1));
          lua_pop(L, 1);
        }
        return arr;
      }
      nlohmann::json obj = nlohmann::json::object();
      lua_pushnil(L);
      while (lua_next(L, idx)) {
        if (lua_type(L, -2) != LUA_TSTRING) throw ArgError("schema: table keys must be strings or 1..n");
        obj[lua_tostring(L, -2)] = to_json(L, -1, depth + 1);
        lua_pop(L, 1);
      }
      return obj;
    }
    default: throw ArgError(std::string("schema: cannot turn a ") + luaL_typename(L, idx) + " into JSON");
  }
}

llm::LlmConfig config_from_table(lua_State* L, int idx) {
  llm::LlmConfig c;
  if (auto env = llm::config_from_env(); env.is_ok()) c = *env;
  const std::string env_url = c.url;
  c.url = field_string(L, idx, "url", c.url);
  // The key from the environment goes only to the server the environment names.
  if (c.url != env_url) c.api_key.clear();
  c.model = field_string(L, idx, "model", c.model);
  get_field(L, idx, "api");
  const bool api_given = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (api_given) {
    auto api = llm::parse_api(field_string(L, idx, "api", ""));
    check_status(api.status());
    c.api = *api;
  } else if (!c.url.empty()) {
    c.api = llm::infer_api(c.url);
  }
  c.temperature = field_number(L, idx, "temperature", c.temperature);
  constexpr long long kIntMax = 2147483647;
  c.seed = field_count(L, idx, "seed", c.seed, 0, 9007199254740992LL);
  c.context_size = static_cast<int>(field_count(L, idx, "context", c.context_size, 1, kIntMax));
  c.max_tokens = static_cast<int>(field_count(L, idx, "max_tokens", c.max_tokens, 1, kIntMax));
  c.timeout_s = field_number(L, idx, "timeout", c.timeout_s);
  c.connect_timeout_s = field_number(L, idx, "connect_timeout", c.connect_timeout_s);
  c.retry.max_attempts = static_cast<int>(field_count(L, idx, "retries", c.retry.max_attempts, 1, 100));
  c.max_reply_bytes = static_cast<size_t>(
      field_count(L, idx, "max_reply_bytes", static_cast<long long>(c.max_reply_bytes), 1, 1LL << 40));
  c.max_line_bytes = static_cast<size_t>(
      field_count(L, idx, "max_line_bytes", static_cast<long long>(c.max_line_bytes), 1, 1LL << 40));
  c.retry.initial_backoff_s = field_number(L, idx, "backoff", c.retry.initial_backoff_s);
  return c;
}

void push_client(lua_State* L, std::unique_ptr<llm::LlmClient> client) {
  new_object<ClientBox>(L, kClientMt)->client = std::move(client);
}

int l_client(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  auto client = llm::make_client(config_from_table(L, 1));
  check_status(client.status());
  push_client(L, std::move(client).value());
  return 1;
}

int l_from_env(lua_State* L) {
  auto cfg = llm::config_from_env();
  auto client = cfg.is_ok() ? llm::make_client(*cfg) : Result<std::unique_ptr<llm::LlmClient>>(cfg.status());
  if (!client) {
    lua_pushnil(L);
    lua_pushstring(L, client.status().message().c_str());
    return 2;
  }
  push_client(L, std::move(client).value());
  return 1;
}

std::vector<llm::Message> read_messages(lua_State* L, int idx) {
  std::vector<llm::Message> msgs;
  if (lua_type(L, idx) == LUA_TSTRING) {
    msgs.push_back({"user", lua_tostring(L, idx)});
    return msgs;
  }
  if (lua_type(L, idx) != LUA_TTABLE) throw ArgError(type_error(L, idx, "messages", "string or table of {role=, content=}"));
  const lua_Integer n = length(L, idx);
  for (lua_Integer i = 1; i <= n; ++i) {
    get_index(L, idx, i);
    if (!lua_istable(L, -1)) throw ArgError("messages[" + std::to_string(i) + "]: expected {role=, content=}");
    msgs.push_back({field_string(L, -1, "role", "user"), field_string(L, -1, "content", "")});
    lua_pop(L, 1);
  }
  return msgs;
}

int l_chat(lua_State* L) {
  auto* box = arg_object<ClientBox>(L, 1, kClientMt);
  const Pin pin(L, 1);  // on_token runs Lua code
  llm::ChatRequest req;
  req.messages = read_messages(L, 2);
  const bool has_opts = lua_istable(L, 3);
  int token_fn = 0;
  if (has_opts) {
    const std::string system = field_string(L, 3, "system", "");
    if (!system.empty()) req.messages.insert(req.messages.begin(), {"system", system});
    req.grammar = field_string(L, 3, "grammar", "");
    get_field(L, 3, "schema");
    if (lua_type(L, -1) == LUA_TSTRING) {
      req.json_schema = nlohmann::json::parse(lua_tostring(L, -1), nullptr, false);
      if (req.json_schema.is_discarded()) throw ArgError("schema: the string is not valid JSON");
    } else if (!lua_isnil(L, -1)) {
      req.json_schema = to_json(L, -1, 0);
    }
    lua_pop(L, 1);
    get_field(L, 3, "on_token");
    if (lua_isfunction(L, -1)) token_fn = lua_gettop(L);
    else lua_pop(L, 1);
  }
  std::string callback_error;
  llm::TokenSink sink;
  if (token_fn) {
    sink = [&](std::string_view piece) {
      if (!callback_error.empty()) return;
      lua_pushvalue(L, token_fn);
      lua_pushlstring(L, piece.data(), piece.size());
      if (lua_pcall(L, 1, 0, 0) != LUA_OK) {
        callback_error = lua_tostring(L, -1) ? lua_tostring(L, -1) : "error in on_token";
        lua_pop(L, 1);
      }
    };
  }
  auto reply = box->client->chat(req, sink);
  if (!callback_error.empty()) throw ArgError("on_token: " + callback_error);
  if (!reply) {
    lua_pushnil(L);
    lua_pushstring(L, reply.status().message().c_str());
    return 2;
  }
  lua_pushlstring(L, reply->content.data(), reply->content.size());
  lua_createtable(L, 0, 5);
  lua_pushstring(L, reply->model.c_str());
  lua_setfield(L, -2, "model");
  lua_pushinteger(L, reply->attempts);
  lua_setfield(L, -2, "attempts");
  lua_pushinteger(L, reply->prompt_tokens);
  lua_setfield(L, -2, "prompt_tokens");
  lua_pushinteger(L, reply->completion_tokens);
  lua_setfield(L, -2, "completion_tokens");
  lua_pushstring(L, reply->finish_reason.c_str());
  lua_setfield(L, -2, "finish_reason");
  return 2;
}

int l_embed(lua_State* L) {
  auto* box = arg_object<ClientBox>(L, 1, kClientMt);
  luaL_checktype(L, 2, LUA_TTABLE);
  std::vector<std::string> texts;
  const lua_Integer n = length(L, 2);
  for (lua_Integer i = 1; i <= n; ++i) {
    get_index(L, 2, i);
    if (lua_type(L, -1) != LUA_TSTRING) throw ArgError("embed: texts[" + std::to_string(i) + "] is not a string");
    texts.emplace_back(lua_tostring(L, -1));
    lua_pop(L, 1);
  }
  auto e = box->client->embed(texts);
  if (!e) {
    lua_pushnil(L);
    lua_pushstring(L, e.status().message().c_str());
    return 2;
  }
  lua_createtable(L, static_cast<int>(e->size()), 0);
  for (size_t i = 0; i < e->size(); ++i) {
    const auto& v = (*e)[i];
    lua_createtable(L, static_cast<int>(v.size()), 0);
    for (size_t j = 0; j < v.size(); ++j) {
      lua_pushnumber(L, v[j]);
      lua_seti(L, -2, static_cast<lua_Integer>(j + 1));
    }
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int l_describe(lua_State* L) {
  auto* box = arg_object<ClientBox>(L, 1, kClientMt);
  lua_pushstring(L, box->client->config().describe().c_str());
  return 1;
}

int l_load_config(lua_State* L) {
  std::string path = arg_string(L, 1, "path");
  if (!path.empty() && path.front() != '/') path = paths::resource(path);
  readable(L, path, "squawk.load_config");
  auto data = files::read(path);
  check_status(data.status());
  if (luaL_loadbufferx(L, data->data(), data->size(), ("@" + path).c_str(), "t") != LUA_OK)
    throw ArgError(lua_tostring(L, -1));
  lua_newtable(L);  // the file's environment
  for (const char* lib : {"string", "table", "math", "utf8", "pairs", "ipairs", "select", "type",
                          "tostring", "tonumber", "error"}) {
    lua_getglobal(L, lib);
    lua_setfield(L, -2, lib);
  }
  if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
  if (lua_pcall(L, 0, 1, 0) != LUA_OK) throw ArgError(path + ": " + error_text(L, -1));
  if (!lua_istable(L, -1))
    throw ArgError(path + ": the file must return a table, it returned a " + luaL_typename(L, -1));
  return 1;
}

}  // namespace

void bind_llm(lua_State* L) {
  const luaL_Reg methods[] = {{"chat", guarded<l_chat>},
                              {"embed", guarded<l_embed>},
                              {"describe", guarded<l_describe>},
                              {nullptr, nullptr}};
  define_class(L, kClientMt, methods);
  push_squawk_subtable(L, "llm");
  lua_pushcfunction(L, guarded<l_client>);
  lua_setfield(L, -2, "client");
  lua_pushcfunction(L, guarded<l_from_env>);
  lua_setfield(L, -2, "from_env");
  lua_pop(L, 1);
  lua_getglobal(L, "squawk");
  lua_pushcfunction(L, guarded<l_load_config>);
  lua_setfield(L, -2, "load_config");
  lua_pop(L, 1);
}

}  // namespace squawk::script
