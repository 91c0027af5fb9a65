#pragma once
// A parsed scene file that knows the line of every element, and a view of one element whose
// attributes are read with $variables expanded.
#include <initializer_list>
#include <memory>
#include <pugixml.hpp>
#include <string>
#include <vector>
#include "core/error.h"
#include "scene/scene_variables.h"

namespace columba {

class XmlDocument {
 public:
  // Throws InputError naming the path if it cannot be read, or at the line of an XML error.
  static std::unique_ptr<XmlDocument> fromFile(const std::string& path);
  // `sourceName` names the text in messages; `baseDir` is where its relative paths lead.
  XmlDocument(const std::string& text, std::string sourceName, std::string baseDir);

  const std::string& sourceName() const { return sourceName_; }
  const std::string& baseDir() const { return baseDir_; }
  SourceLocation locate(const pugi::xml_node& node) const;
  // The single top-level element.
  pugi::xml_node root() const;

 private:
  SourceLocation locateOffset(ptrdiff_t offset) const;
  std::string sourceName_, baseDir_;
  std::vector<size_t> lineStarts_;
  pugi::xml_document doc_;
};

class XmlElement {
 public:
  XmlElement(pugi::xml_node node, const XmlDocument& doc, const SceneVariables& vars)
      : node_(node), doc_(&doc), vars_(&vars), location_(doc.locate(node)) {}

  std::string tag() const { return node_.name(); }
  const SourceLocation& location() const { return location_; }
  const XmlDocument& document() const { return *doc_; }

  bool has(const char* name) const { return bool(node_.attribute(name)); }
  // The attribute's value with $variables expanded; the first form throws if it is missing.
  std::string attribute(const char* name) const;
  std::string attribute(const char* name, const std::string& def) const;
  // Throws for any attribute not in `allowed`, so that misspelt ones are not silently ignored.
  void allowAttributes(std::initializer_list<const char*> allowed) const;

  // The nested elements in document order; text content is an error.
  std::vector<XmlElement> children() const;
  void requireNoChildren() const;

 private:
  pugi::xml_node node_;
  const XmlDocument* doc_;
  const SceneVariables* vars_;
  SourceLocation location_;
};

}  // namespace columba
