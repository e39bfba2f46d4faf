#pragma once
// XML read back with libxml2 for the XDMF tests: a document that frees itself, elements by tag,
// attributes and text.
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <filesystem>
#include <string>
#include <vector>

namespace host_test {

struct XmlDoc {
  explicit XmlDoc(const std::filesystem::path& file) : doc(xmlReadFile(file.c_str(), nullptr, XML_PARSE_NONET)) {}
  ~XmlDoc() { xmlFreeDoc(doc); }
  xmlDoc* doc;
};

inline void collect(xmlNode* node, const std::string& tag, std::vector<xmlNode*>& out) {
  for (xmlNode* c = node; c; c = c->next) {
    if (c->type == XML_ELEMENT_NODE && tag == reinterpret_cast<const char*>(c->name)) out.push_back(c);
    collect(c->children, tag, out);
  }
}

inline std::string prop(xmlNode* n, const char* key) {
  xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(key));
  std::string s = v ? reinterpret_cast<const char*>(v) : "";
  xmlFree(v);
  return s;
}

inline std::string content(xmlNode* n) {
  xmlChar* v = xmlNodeGetContent(n);
  std::string s = v ? reinterpret_cast<const char*>(v) : "";
  xmlFree(v);
  return s;
}

}  // namespace host_test
