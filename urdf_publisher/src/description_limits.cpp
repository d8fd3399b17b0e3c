#include "lcmtf_urdf/description_limits.hpp"

#include <algorithm>
#include <cctype>

#include "lcmtf_urdf/robot_model.hpp"

// Why these limits: the robots in the wild nest 5 to 10 deep (robot, link, visual, geometry,
// mesh, plus a plugin's own tags), have at most a few hundred links and about 20 elements per
// link. TinyXML parses, and urdfdom frees its tree of links, by recursion, one call per level;
// both overflow the stack some tens of thousands deep, sooner under sanitizers or on smaller
// thread stacks. 256 levels and 10,000 links leave room for any robot and for the recursion;
// 200,000 elements are 10,000 links of the usual richness, about a second and 70 MB of parsing,
// where a million would take five seconds and 350 MB, twice over (TinyXML and urdfdom).

namespace lcmtf::urdf {

namespace {

// The characters TinyXML starts an element name with after '<' (DEL and every byte above
// ASCII among them); any other '<' it reads as unknown markup up to the next '>'.
bool startsName(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return (byte >= 'a' && byte <= 'z') || (byte >= 'A' && byte <= 'Z') || byte == '_' ||
         byte >= 0x7f;
}

bool isWhitespace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

bool continuesName(char c) {
  return startsName(c) || (c >= '0' && c <= '9') || c == '-' || c == '.' || c == ':';
}

// Reads the markup as TinyXML does, so nothing that TinyXML would parse as an element is
// hidden from the count, and nothing it skips counts as closing one.
class DescriptionScanner {
 public:
  explicit DescriptionScanner(std::string_view text) : text_(text) {}

  DescriptionShape scan() {
    if (cutsUtf8Short()) {
      shape_.unreadable = "bytes that are not UTF-8 (a character cut short)";
      return shape_;
    }
    for (std::size_t at = text_.find('<'); at != std::string_view::npos;
         at = text_.find('<', pastMarkupAt(at))) {
    }
    return shape_;
  }

 private:
  // One past the end of the markup that starts with the '<' at `at`.
  std::size_t pastMarkupAt(std::size_t at) {
    const char next = at + 1 < text_.size() ? text_[at + 1] : '\0';
    if (startsName(next)) return pastElementTag(at + 1);
    if (next == '/') {
      leaveElement();
      return pastNext(at + 2, ">");
    }
    if (startsWithXmlDeclaration(at)) return pastXmlDeclaration(at + 5);
    if (startsWith(at, "<!--")) return pastNext(at + 4, "-->");
    if (startsWith(at, "<![CDATA[")) return pastNext(at + 9, "]]>");
    // Declarations, processing instructions, DOCTYPE, stray '<': up to the first '>', even
    // one inside quotes, as TinyXML reads them.
    return pastNext(at + 1, ">");
  }

  // TinyXML honours quotes in a declaration only around the values of its own attributes
  // (version, encoding, standalone), and ends it at the first '>' outside them. When no quoted
  // value holds whitespace or a '>', every reading ends at the first '>'; at any other
  // declaration the scan stops.
  std::size_t pastXmlDeclaration(std::size_t from) {
    const std::size_t end = std::min(text_.find('>', from), text_.size());
    for (std::size_t at = from; at < end; ++at) {
      if (text_[at] != '"' && text_[at] != '\'') continue;
      const std::size_t closing = std::min(text_.find(text_[at], at + 1), text_.size());
      if (closing > end || std::any_of(text_.data() + at, text_.data() + closing, isWhitespace)) {
        shape_.unreadable = "an XML declaration with whitespace or '>' inside quotes";
        return text_.size();
      }
      at = closing;
    }
    return std::min(end + 1, text_.size());
  }

  std::size_t pastElementTag(std::size_t after_less_than) {
    const std::size_t name_start = pastSkippedBeforeName(after_less_than);
    std::size_t at = name_start;
    while (at < text_.size() && continuesName(text_[at])) ++at;
    ++shape_.elements;
    if (text_.substr(name_start, at - name_start) == "link") ++shape_.links;
    // A '>' or '/' inside a quoted attribute value ends nothing.
    for (; at < text_.size() && text_[at] != '>'; ++at) {
      if (text_[at] == '"' || text_[at] == '\'') {
        at = text_.find(text_[at], at + 1);
        if (at == std::string_view::npos) break;
      }
    }
    enterElement();
    if (at >= text_.size()) return text_.size();
    if (text_[at - 1] == '/') leaveElement();
    return at + 1;
  }

  // TinyXML reading UTF-8 (a document that starts with a byte-order mark, or whose XML
  // declaration names UTF-8 or no encoding) skips whitespace, the byte-order mark and the
  // non-characters U+FFFE and U+FFFF between '<' and an element's name: "<\xEF\xBB\xBFlink" is a
  // link to it. They are skipped here whatever the encoding, so a document in another one may count
  // a link too many, never one too few.
  std::size_t pastSkippedBeforeName(std::size_t from) const {
    while (from < text_.size()) {
      if (startsWith(from, "\xEF\xBB\xBF") || startsWith(from, "\xEF\xBF\xBE") ||
          startsWith(from, "\xEF\xBF\xBF")) {
        from += 3;
      } else if (isWhitespace(text_[from])) {
        ++from;
      } else {
        break;
      }
    }
    return from;
  }

  void enterElement() {
    ++depth_;
    shape_.deepest_nesting = std::max(shape_.deepest_nesting, depth_);
  }

  void leaveElement() {
    if (depth_ > 0) --depth_;
  }

  // TinyXML reading UTF-8 takes the bytes after a multi-byte lead as part of its character,
  // whatever they are: a '<' there would be markup to the scan and none to TinyXML. Valid
  // UTF-8 has only continuation bytes there, which are never markup.
  bool cutsUtf8Short() const {
    for (std::size_t at = 0; at < text_.size(); ++at) {
      const auto byte = static_cast<unsigned char>(text_[at]);
      if (byte < 0xC0) continue;
      const std::size_t continuations = byte >= 0xF0 ? 3 : byte >= 0xE0 ? 2 : 1;
      if (text_.size() - at <= continuations) return true;
      for (std::size_t k = 1; k <= continuations; ++k) {
        if (static_cast<unsigned char>(text_[at + k]) < 0x80) return true;
      }
    }
    return false;
  }

  // TinyXML takes "<?XML" and any other spelling for a declaration too.
  bool startsWithXmlDeclaration(std::size_t at) const {
    constexpr std::string_view kStart = "<?xml";
    if (text_.size() - at < kStart.size()) return false;
    for (std::size_t i = 0; i < kStart.size(); ++i) {
      if (std::tolower(static_cast<unsigned char>(text_[at + i])) != kStart[i]) return false;
    }
    return true;
  }

  bool startsWith(std::size_t at, std::string_view prefix) const {
    return text_.compare(at, prefix.size(), prefix) == 0;
  }

  std::size_t pastNext(std::size_t from, std::string_view end) const {
    const std::size_t found = text_.find(end, from);
    return found == std::string_view::npos ? text_.size() : found + end.size();
  }

  std::string_view text_;
  std::size_t depth_ = 0;
  DescriptionShape shape_;
};

}  // namespace

DescriptionShape measureDescription(std::string_view text) {
  return DescriptionScanner(text).scan();
}

void refuseOversizedDescription(std::string_view text, const std::string& source,
                                const DescriptionLimits& limits) {
  const DescriptionShape shape = measureDescription(text);
  const auto refuse = [&source](const std::string& what, std::size_t limit) {
    throw UrdfError(source + ": " + what + "; the limit is " + std::to_string(limit));
  };
  if (!shape.unreadable.empty()) {
    throw UrdfError(source + ": " + shape.unreadable + ", which the size check cannot read");
  }
  if (shape.deepest_nesting > limits.max_nesting) {
    refuse("elements nested " + std::to_string(shape.deepest_nesting) + " deep",
           limits.max_nesting);
  }
  if (shape.links > limits.max_links) {
    refuse(std::to_string(shape.links) + " links", limits.max_links);
  }
  if (shape.elements > limits.max_elements) {
    refuse(std::to_string(shape.elements) + " XML elements", limits.max_elements);
  }
}

}  // namespace lcmtf::urdf
