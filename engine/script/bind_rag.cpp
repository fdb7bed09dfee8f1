// squawk.rag: BM25 retrieval over the command documentation.
//
//   squawk.rag.index([{notes = path, docs = {{command=, text=}, ...}}])
//       An index of one document per registry command, with the notes file
//       (NAME: text lines; none by default) and `docs` appended to the
//       commands they name. The translation graph passes the grammar's words
//       (require("translate.grammar").documents()).
//   index:search(query, [k = 5]) -> {{command=, score=, text=}, ...} best first
//   index:size()                  -> number of documents
#include "command/registry.h"
#include "core/paths.h"
#include "rag/bm25.h"
#include "rag/notes.h"
#include "script/bindings.h"
#include "script/lua_util.h"

namespace squawk::script {

namespace {

constexpr const char* kIndexMt = "squawk.rag.Index";

std::vector<rag::Document> read_docs(lua_State* L, int opts) {
  std::vector<rag::Document> docs;
  get_field(L, opts, "docs");
  if (lua_istable(L, -1)) {
    const lua_Integer n = length(L, -1);
    for (lua_Integer i = 1; i <= n; ++i) {
      get_index(L, -1, i);
      if (!lua_istable(L, -1)) throw ArgError("docs[" + std::to_string(i) + "]: expected {command=, text=}");
      docs.push_back({field_string(L, -1, "command", ""), field_string(L, -1, "text", "")});
      lua_pop(L, 1);
    }
  } else if (!lua_isnil(L, -1)) {
    throw ArgError("docs: expected a table of {command=, text=}");
  }
  lua_pop(L, 1);
  return docs;
}

int l_index(lua_State* L) {
  const bool has_opts = lua_istable(L, 1);
  std::vector<rag::Document> extra;
  std::string notes_path;
  if (has_opts) {
    get_field(L, 1, "notes");
    if (lua_type(L, -1) == LUA_TSTRING) notes_path = lua_tostring(L, -1);
    lua_pop(L, 1);
  }
  if (!notes_path.empty()) {
    auto notes = rag::read_notes(readable(L, notes_path, "squawk.rag.index{notes}"));
    check_status(notes.status());
    extra = std::move(notes).value();
  }
  if (has_opts) {
    auto docs = read_docs(L, 1);
    extra.insert(extra.end(), docs.begin(), docs.end());
  }
  new_object<rag::Bm25Index>(L, kIndexMt, rag::command_documents(command::Registry::instance(), extra));
  return 1;
}

int l_search(lua_State* L) {
  auto* idx = arg_object<rag::Bm25Index>(L, 1, kIndexMt);
  const std::string query = arg_string(L, 2, "query");
  const long long k = opt_integer(L, 3, "k", 5);
  if (k < 1) throw ArgError("k must be at least 1");
  const auto hits = idx->search(query, static_cast<size_t>(k));
  lua_createtable(L, static_cast<int>(hits.size()), 0);
  for (size_t i = 0; i < hits.size(); ++i) {
    const auto& d = idx->documents()[hits[i].doc];
    lua_createtable(L, 0, 3);
    lua_pushstring(L, d.command.c_str());
    lua_setfield(L, -2, "command");
    lua_pushnumber(L, hits[i].score);
    lua_setfield(L, -2, "score");
    lua_pushlstring(L, d.text.data(), d.text.size());
    lua_setfield(L, -2, "text");
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int l_size(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(arg_object<rag::Bm25Index>(L, 1, kIndexMt)->documents().size()));
  return 1;
}

}  // namespace

void bind_rag(lua_State* L) {
  const luaL_Reg methods[] = {{"search", guarded<l_search>}, {"size", guarded<l_size>}, {nullptr, nullptr}};
  define_class(L, kIndexMt, methods);
  push_squawk_subtable(L, "rag");
  lua_pushcfunction(L, guarded<l_index>);
  lua_setfield(L, -2, "index");
  lua_pop(L, 1);
}

}  // namespace squawk::script
