#include "scene/xml_source.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace columba {

std::unique_ptr<XmlDocument> XmlDocument::fromFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path, 0}, "cannot open scene file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return std::make_unique<XmlDocument>(text.str(), path, std::filesystem::path(path).parent_path().string());
}

XmlDocument::XmlDocument(const std::string& text, std::string sourceName, std::string baseDir)
    : sourceName_(std::move(sourceName)), baseDir_(std::move(baseDir)) {
  lineStarts_.push_back(0);
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') lineStarts_.push_back(i + 1);
  pugi::xml_parse_result result = doc_.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!result) throw InputError(locateOffset(result.offset), std::string("malformed XML: ") + result.description());
}

SourceLocation XmlDocument::locateOffset(ptrdiff_t offset) const {
  if (offset < 0) return SourceLocation{sourceName_, 0};
  auto next = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), size_t(offset));
  return SourceLocation{sourceName_, int(next - lineStarts_.begin())};
}

SourceLocation XmlDocument::locate(const pugi::xml_node& node) const { return locateOffset(node.offset_debug()); }

pugi::xml_node XmlDocument::root() const {
  pugi::xml_node root;
  for (pugi::xml_node n : doc_.children()) {
    if (n.type() != pugi::node_element) throw InputError(locate(n), "unexpected text outside the root element");
    if (root) throw InputError(locate(n), "a second top-level element <" + std::string(n.name()) + ">");
    root = n;
  }
  if (!root) throw InputError(SourceLocation{sourceName_, 0}, "no root element");
  return root;
}

std::string XmlElement::attribute(const char* name) const {
  pugi::xml_attribute a = node_.attribute(name);
  if (!a) throw InputError(location_, "<" + tag() + "> is missing the attribute '" + name + "'");
  return vars_->substitute(a.value(), location_);
}

std::string XmlElement::attribute(const char* name, const std::string& def) const {
  pugi::xml_attribute a = node_.attribute(name);
  return a ? vars_->substitute(a.value(), location_) : def;
}

void XmlElement::allowAttributes(std::initializer_list<const char*> allowed) const {
  for (pugi::xml_attribute a : node_.attributes())
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* n) { return std::string(n) == a.name(); }))
      throw InputError(location_, "unexpected attribute '" + std::string(a.name()) + "' in <" + tag() + ">");
}

std::vector<XmlElement> XmlElement::children() const {
  std::vector<XmlElement> out;
  for (pugi::xml_node n : node_.children()) {
    if (n.type() != pugi::node_element)
      throw InputError(doc_->locate(n), "unexpected text '" + std::string(n.value()) + "' in <" + tag() + ">");
    out.emplace_back(n, *doc_, *vars_);
  }
  return out;
}

void XmlElement::requireNoChildren() const {
  if (!node_.children().empty()) throw InputError(location_, "<" + tag() + "> takes no nested elements");
}

}  // namespace columba
