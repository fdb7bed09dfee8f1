// Document: one retrievable chunk of API documentation.
//
// The registry documents (one per TrafScript command) hold the name, aliases,
// usage, help paragraph and examples, so BM25 can match a request's words to
// the command's description; extra documents (the grammar's words, user notes)
// name the command they point to and add text of their own.
#pragma once

#include <string>
#include <vector>

namespace squawk::command {
class Registry;
}

namespace squawk::rag {

struct Document {
  std::string command;  // canonical command name this chunk documents
  std::string text;     // what is indexed and shown to the LLM
};

// One document per registry command, in registry order:
//   "NAME (aliases: A, B)\nUsage: ...\nhelp\nExamples: ...".
std::vector<Document> registry_documents(const command::Registry& registry);

// registry_documents() with each `extra` document appended to the document of
// the command it names (by name or alias, folded to the canonical name); an
// extra document naming no known command stays a document of its own.
std::vector<Document> command_documents(const command::Registry& registry,
                                        const std::vector<Document>& extra);

}  // namespace squawk::rag
