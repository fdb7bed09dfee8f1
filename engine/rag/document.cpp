#include "rag/document.h"

#include "command/registry.h"
#include "core/text.h"

namespace squawk::rag {

std::vector<Document> registry_documents(const command::Registry& registry) {
  std::vector<Document> docs;
  for (const auto& c : registry.commands()) {
    std::string t = c.name;
    if (!c.aliases.empty()) t.append(" (aliases: ").append(text::join(c.aliases, ", ")).append(")");
    t.append("\nUsage: ").append(c.usage).append("\n").append(c.help);
    if (!c.examples.empty()) t.append("\nExamples: ").append(text::join(c.examples, " | "));
    docs.push_back({c.name, std::move(t)});
  }
  return docs;
}

std::vector<Document> command_documents(const command::Registry& registry,
                                        const std::vector<Document>& extra) {
  auto docs = registry_documents(registry);
  for (const auto& e : extra) {
    const auto* decl = registry.find(e.command);
    Document* target = nullptr;
    if (decl)
      for (auto& d : docs)
        if (d.command == decl->name) target = &d;
    if (target)
      target->text.append("\n").append(e.text);
    else
      docs.push_back(e);
  }
  return docs;
}

}  // namespace squawk::rag
