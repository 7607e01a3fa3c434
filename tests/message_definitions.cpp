#include "message_definitions.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

namespace scanfilter::test {

namespace {

// The ROS 2 DDS naming: the types of package P live in module P::msg::dds_.
constexpr std::string_view kMsgModule = "msg";
constexpr std::string_view kDdsModule = "dds_";
constexpr std::size_t kRosModuleDepth = 3;  // P, msg, dds_

// IDL base types as a .msg spells them (the ROS 2 mapping). `char` is int8:
// idl/scanfilter_types.idl writes ROS 2's int8 as char, one byte in both
// code generators.
const std::map<std::string, std::string, std::less<>>& idlBaseTypes() {
  static const std::map<std::string, std::string, std::less<>> types = {
      {"short", "int16"},        {"unsigned short", "uint16"},
      {"long", "int32"},         {"unsigned long", "uint32"},
      {"long long", "int64"},    {"unsigned long long", "uint64"},
      {"float", "float32"},      {"double", "float64"},
      {"long double", "float128"}, {"boolean", "bool"},
      {"octet", "uint8"},        {"char", "int8"},
      {"wchar", "wchar"},        {"string", "string"},
      {"wstring", "wstring"},    {"int8", "int8"},
      {"uint8", "uint8"},        {"int16", "int16"},
      {"uint16", "uint16"},      {"int32", "int32"},
      {"uint32", "uint32"},      {"int64", "int64"},
      {"uint64", "uint64"}};
  return types;
}

// The DDS name of a ROS 2 type carries a trailing underscore.
std::string withoutTrailingUnderscore(std::string name) {
  if (!name.empty() && name.back() == '_') name.pop_back();
  return name;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Identifiers, numbers, string literals, "::" and single punctuation marks;
// comments and preprocessor lines are dropped.
std::vector<std::string> idlTokens(std::string_view text) {
  std::vector<std::string> tokens;
  std::size_t i = 0;
  const auto skipTo = [&](std::string_view end, bool required) {
    const std::size_t at = text.find(end, i);
    if (at == std::string_view::npos && required) throw std::runtime_error("IDL: unterminated comment");
    i = at == std::string_view::npos ? text.size() : at + end.size();
  };
  while (i < text.size()) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (text.substr(i, 2) == "//" || c == '#') {
      skipTo("\n", false);
    } else if (text.substr(i, 2) == "/*") {
      i += 2;
      skipTo("*/", true);
    } else if (text.substr(i, 2) == "::") {
      tokens.emplace_back("::");
      i += 2;
    } else if (isIdentifierChar(c)) {
      const std::size_t start = i;
      while (i < text.size() && (isIdentifierChar(text[i]) || text[i] == '.')) ++i;
      tokens.emplace_back(text.substr(start, i - start));
    } else if (c == '"') {
      const std::size_t start = i++;
      while (i < text.size() && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
      tokens.emplace_back(text.substr(start, ++i - start));
    } else {
      tokens.emplace_back(1, c);
      ++i;
    }
  }
  return tokens;
}

class IdlParser {
 public:
  explicit IdlParser(std::vector<std::string> tokens) : tokens_(std::move(tokens)) {}

  std::map<std::string, MessageFields> parse() {
    definitions();
    if (!atEnd()) fail("unexpected `" + peek() + "`");
    return structs_;
  }

 private:
  bool atEnd() const { return pos_ >= tokens_.size(); }
  const std::string& peek() const {
    static const std::string kEnd;
    return atEnd() ? kEnd : tokens_[pos_];
  }
  std::string next() {
    if (atEnd()) fail("unexpected end of the text");
    return tokens_[pos_++];
  }
  void expect(std::string_view token) {
    if (next() != token) fail("expected `" + std::string(token) + "`");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("IDL, token " + std::to_string(pos_) + ": " + what);
  }

  void definitions() {
    while (!atEnd() && peek() != "}") definition();
  }

  void definition() {
    skipAnnotations();
    const std::string keyword = next();
    if (keyword == "module") {
      modules_.push_back(next());
      expect("{");
      definitions();
      expect("}");
      expect(";");
      modules_.pop_back();
    } else if (keyword == "struct") {
      structure();
    } else {
      skipDeclaration();  // const, typedef, enum, union: no fields of a message
    }
  }

  void structure() {
    const std::string name = next();
    if (peek() == ";") return next(), void();  // a forward declaration
    expect("{");
    MessageFields fields;
    while (peek() != "}") member(fields);
    expect("}");
    expect(";");
    structs_[rosName(name)] = std::move(fields);
  }

  void member(MessageFields& fields) {
    skipAnnotations();
    const std::string type = typeSpec();
    do {
      const std::string name = next();
      std::string dimensions;
      while (peek() == "[") {
        next();
        dimensions += "[" + next() + "]";
        expect("]");
      }
      fields.push_back({type + dimensions, name});
    } while (peek() == "," && (next(), true));
    expect(";");
  }

  // The type of a member, as a .msg spells it.
  std::string typeSpec() {
    std::string word = next();
    if (word == "unsigned") word += " " + next();
    if ((word == "long" || word == "unsigned long") && (peek() == "long" || peek() == "double")) word += " " + next();
    if (word == "sequence") {
      expect("<");
      const std::string element = typeSpec();
      std::string bound;
      if (peek() == ",") next(), bound = next();
      expect(">");
      return element + (bound.empty() ? "[]" : "[<=" + bound + "]");
    }
    if ((word == "string" || word == "wstring") && peek() == "<") {
      next();
      const std::string bound = next();
      expect(">");
      return word + "<=" + bound;
    }
    if (const auto base = idlBaseTypes().find(word); base != idlBaseTypes().end()) return base->second;
    std::vector<std::string> scope = {word};
    while (peek() == "::") next(), scope.push_back(next());
    return rosTypeReference(scope);
  }

  // P::msg::dds_::X_ is P/X, or X alone within package P; a name without
  // scope is a type of the struct's own module.
  std::string rosTypeReference(const std::vector<std::string>& scope) const {
    if (scope.size() == 1) return withoutTrailingUnderscore(scope[0]);
    if (scope.size() == kRosModuleDepth + 1 && scope[1] == kMsgModule && scope[2] == kDdsModule) {
      const std::string type = withoutTrailingUnderscore(scope.back());
      return scope[0] == currentPackage() ? type : scope[0] + "/" + type;
    }
    std::string joined;
    for (const auto& part : scope) joined += (joined.empty() ? "" : "::") + part;
    return joined;  // not a ROS 2 type: shown as written, so it differs visibly
  }

  std::string currentPackage() const {
    const bool ros = modules_.size() == kRosModuleDepth && modules_[1] == kMsgModule && modules_[2] == kDdsModule;
    return ros ? modules_[0] : std::string();
  }

  std::string rosName(const std::string& struct_name) const {
    if (!currentPackage().empty()) return currentPackage() + "/" + withoutTrailingUnderscore(struct_name);
    std::string scoped;
    for (const auto& module : modules_) scoped += module + "::";
    return scoped + struct_name;
  }

  // @key, @default(value = 0), @verbatim(language = "comment", text = "…")
  void skipAnnotations() {
    while (peek() == "@") {
      next();
      next();
      while (peek() == "::") next(), next();
      if (peek() == "(") skipBalanced("(", ")");
    }
  }

  void skipBalanced(std::string_view open, std::string_view close) {
    int depth = 0;
    do {
      const std::string token = next();
      depth += token == open ? 1 : token == close ? -1 : 0;
    } while (depth > 0);
  }

  void skipDeclaration() {
    while (peek() != ";") {
      if (peek() == "{") skipBalanced("{", "}");
      else next();
    }
    next();
  }

  std::vector<std::string> tokens_;
  std::size_t pos_ = 0;
  std::vector<std::string> modules_;
  std::map<std::string, MessageFields> structs_;
};

// A line of a .msg without its comment (a # outside a quoted default value).
std::string withoutComment(const std::string& line) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) quote = c == quote ? 0 : quote;
    else if (c == '"' || c == '\'') quote = c;
    else if (c == '#') return line.substr(0, i);
  }
  return line;
}

// A .msg type with the message's own package left out (ROS 2 allows both
// spellings). `byte` is the one-byte unsigned type, as IDL's octet is.
std::string msgType(const std::string& type, std::string_view package) {
  const std::size_t array = std::min(type.find('['), type.size());
  std::string base = type.substr(0, array);
  const std::string suffix = type.substr(array);
  const std::string own_prefix = std::string(package) + "/";
  if (base.starts_with(own_prefix)) base.erase(0, own_prefix.size());
  if (base == "byte") base = "uint8";
  return base + suffix;
}

std::string quoted(const MessageField& field) { return "`" + field.type + " " + field.name + "`"; }

}  // namespace

MessageFields parseMsgFields(std::string_view msg_text, std::string_view package) {
  MessageFields fields;
  std::istringstream lines{std::string(msg_text)};
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(withoutComment(line));
    std::string type, name, after;
    if (!(words >> type)) continue;  // blank or a comment
    if (!(words >> name)) throw std::runtime_error(".msg: a type without a field name: " + line);
    const bool constant = name.find('=') != std::string::npos || ((words >> after) && after.starts_with("="));
    if (!constant) fields.push_back({msgType(type, package), name});
  }
  return fields;
}

std::map<std::string, MessageFields> parseIdlStructs(std::string_view idl_text) {
  return IdlParser(idlTokens(idl_text)).parse();
}

std::string firstDifference(const MessageFields& idl, const MessageFields& msg) {
  for (std::size_t i = 0; i < std::max(idl.size(), msg.size()); ++i) {
    const std::string field = "field " + std::to_string(i + 1) + " ";
    if (i >= idl.size()) return field + quoted(msg[i]) + " is in the .msg only";
    if (i >= msg.size()) return field + quoted(idl[i]) + " is in the IDL only";
    if (idl[i] != msg[i])
      return field + "differs: IDL " + quoted(idl[i]) + " (as .msg types), .msg " + quoted(msg[i]);
  }
  return {};
}

}  // namespace scanfilter::test
