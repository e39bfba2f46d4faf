#pragma once
// What the model-description tests share to read XML with libxml2: a parsed document freed on
// destruction, attributes and child elements.
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <catch2/catch.hpp>
#include <optional>
#include <string>
#include <vector>

struct XmlDocument {
  explicit XmlDocument(const char* path) : doc(xmlReadFile(path, nullptr, XML_PARSE_NONET)) { REQUIRE(doc != nullptr); }
  explicit XmlDocument(const std::string& text)
      : doc(xmlReadMemory(text.data(), static_cast<int>(text.size()), "memory.xml", nullptr, XML_PARSE_NONET)) {
    REQUIRE(doc != nullptr);
  }
  ~XmlDocument() { xmlFreeDoc(doc); }
  XmlDocument(const XmlDocument&) = delete;
  XmlDocument& operator=(const XmlDocument&) = delete;
  xmlNodePtr root() const { return xmlDocGetRootElement(doc); }
  xmlDocPtr doc;
};

inline std::optional<std::string> optionalAttribute(xmlNodePtr node, const char* name) {
  xmlChar* v = xmlGetProp(node, BAD_CAST name);
  if (!v) return std::nullopt;
  std::string s = reinterpret_cast<const char*>(v);
  xmlFree(v);
  return s;
}

// The attribute's value, or `fallback` where it is absent.
inline std::string attribute(xmlNodePtr node, const char* name, std::string fallback = "") {
  return optionalAttribute(node, name).value_or(std::move(fallback));
}

inline std::string elementName(xmlNodePtr node) { return reinterpret_cast<const char*>(node->name); }

// The child elements of `node` (of one name, or all); none for a null node.
inline std::vector<xmlNodePtr> children(xmlNodePtr node, const char* name = nullptr) {
  std::vector<xmlNodePtr> out;
  if (!node) return out;
  for (xmlNodePtr c = node->children; c; c = c->next)
    if (c->type == XML_ELEMENT_NODE && (!name || elementName(c) == name)) out.push_back(c);
  return out;
}

// The first child element of that name, or null.
inline xmlNodePtr firstChild(xmlNodePtr node, const char* name) {
  const auto all = children(node, name);
  return all.empty() ? nullptr : all.front();
}
