#include "config/toml_reader.hpp"

#include <fmt/format.h>

#include "config/text_lines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace geartrib::io {

namespace {

// Beyond 2^53 not every integer is a double: such a TOML integer is refused, not rounded.
constexpr std::int64_t kMaxExactInteger = std::int64_t{1} << 53;

// A TOML number (integer or float) as a double in `v`; the rule it breaks, or "" when none.
std::string number_problem(const toml::node& n, double& v) {
  if (n.is_integer()) {
    const std::int64_t i = n.as_integer()->get();
    if (i > kMaxExactInteger || i < -kMaxExactInteger)
      return "integer beyond 2^53 = 9007199254740992: not exactly a number here; write it as a float (a decimal "
             "point or an exponent)";
    v = static_cast<double>(i);
    return "";
  }
  v = n.as_floating_point()->get();
  return std::isfinite(v) ? "" : "value must be finite";
}

}  // namespace

TomlReader::TomlReader(const std::filesystem::path& file) : file_(file.string()) {
  text_ = read_data_file(file, kMaxTomlFileBytes);  // a regular file of at most 1 MiB
  parse();
}

TomlReader::TomlReader(std::string text, const std::filesystem::path& name, const std::filesystem::path& directory)
    : file_(name.string()), directory_(directory), text_(std::move(text)) {
  if (text_.size() > kMaxTomlFileBytes)
    throw InputError(file_, 0, "", "",
                     fmt::format("{} bytes of TOML: at most {} (1 MiB)", text_.size(), kMaxTomlFileBytes));
  parse();
}

void TomlReader::parse() {
  try {
    root_ = toml::parse(text_, file_);
  } catch (const toml::parse_error& e) {
    throw InputError(file_, static_cast<int>(e.source().begin.line), "", "",
                     "TOML syntax error: " + std::string(e.description()));
  }
}

namespace {

// A value typed on the command line as TOML when it parses as one ("30", "0.1", "\"x\""), else
// nothing.
std::optional<toml::table> toml_value(const std::string& text) {
  try {
    toml::table parsed = toml::parse("v = " + text);
    if (parsed.contains("v") && parsed.size() == 1) return parsed;
  } catch (const toml::parse_error&) {
  }
  return std::nullopt;
}

// A bracketed list typed without TOML's quotes, [real_area, plastic_fraction]: an array of its
// comma-separated items, each a TOML value when it parses as one, else its text as a string (as
// a single value is); nothing for other text or an empty item.
std::optional<toml::array> bare_list(std::string_view text) {
  auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
  };
  text = trim(text);
  if (text.size() < 2 || text.front() != '[' || text.back() != ']') return std::nullopt;
  text = text.substr(1, text.size() - 2);
  toml::array out;
  while (true) {
    const auto comma = text.find(',');
    const std::string item(trim(text.substr(0, comma)));
    if (item.empty()) return std::nullopt;
    if (const auto parsed = toml_value(item)) out.push_back(*parsed->get("v"));
    else out.push_back(item);
    if (comma == std::string_view::npos) return out;
    text.remove_prefix(comma + 1);
  }
}

}  // namespace

void TomlReader::set(std::string_view key, const std::string& value_text) {
  const std::string where = file_ + " (--set " + std::string(key) + "=" + value_text + ")";
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string_view::npos)
    throw InputError(where, 0, std::string(key), value_text, "expected a dotted key such as gear_pair.module");
  // No control characters (a tab aside), as in a TOML file's strings: a NUL would cut every message
  // that quotes the value.
  const auto control = [](char ch) { return (static_cast<unsigned char>(ch) < 0x20 && ch != '\t') || ch == 0x7f; };
  if (std::any_of(key.begin(), key.end(), control) || std::any_of(value_text.begin(), value_text.end(), control))
    throw InputError(where, 0, std::string(key), value_text,
                     "a --set key or value may not hold control characters (shown as \\xNN)");
  // The value: a TOML value when it parses as one, else a bracketed list of bare words as an
  // array, else the text as a string ("4mm").
  const std::optional<toml::table> parsed = toml_value(value_text);
  const std::optional<toml::array> list = parsed ? std::nullopt : bare_list(value_text);
  toml::table* t = &root_;
  std::string_view rest = key;
  std::string prefix;
  while (true) {
    const auto dot = rest.find('.');
    const std::string part(rest.substr(0, dot));
    if (dot == std::string_view::npos) {
      if (parsed) t->insert_or_assign(part, *parsed->get("v"));
      else if (list) t->insert_or_assign(part, *list);
      else t->insert_or_assign(part, value_text);
      break;
    }
    prefix += (prefix.empty() ? "" : ".") + part;
    toml::node* n = t->get(part);
    if (!n) n = &t->insert_or_assign(part, toml::table{}).first->second;
    if (!n->is_table())
      throw InputError(where, 0, prefix, "", "is a value, not a table: cannot set " + std::string(key));
    t = n->as_table();
    rest.remove_prefix(dot + 1);
  }
  changed_[std::string(key)] = value_text;
}

void TomlReader::erase(std::string_view key) {
  const auto dot = key.rfind('.');
  toml::node* parent = dot == std::string_view::npos ? &root_ : root_.at_path(key.substr(0, dot)).node();
  if (parent && parent->is_table())
    parent->as_table()->erase(std::string(key.substr(dot == std::string_view::npos ? 0 : dot + 1)));
}

const toml::node* TomlReader::find(std::string_view key) const { return root_.at_path(key).node(); }

bool TomlReader::has(std::string_view key) const { return find(key) != nullptr; }

bool TomlReader::is_string(std::string_view key) const {
  const toml::node* n = find(key);
  return n && n->is_string();
}

bool TomlReader::is_bare_number(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return false;
  if (n->is_integer() || n->is_floating_point()) return true;
  if (!n->is_string()) return false;
  const auto any = parse_any_quantity(n->as_string()->get());
  return any && any->dimension == Dimension::dimensionless;
}

int TomlReader::line_of(std::string_view key) const {
  // The key's own line, else the nearest enclosing table that exists.
  std::string k(key);
  while (true) {
    if (const toml::node* n = find(k)) return static_cast<int>(n->source().begin.line);
    const auto dot = k.rfind('.');
    if (dot == std::string::npos) return 0;
    k.resize(dot);
  }
}

std::string TomlReader::value_text(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n) return "";
  // As the file writes it: strings quoted, floats by their shortest round trip (0.7), arrays item by item.
  const auto scalar = [](const toml::node& v) {
    std::ostringstream os;
    if (v.is_string()) os << '"' << v.as_string()->get() << '"';
    else if (v.is_floating_point()) os << fmt::format("{}", v.as_floating_point()->get());
    else if (v.is_table()) os << "(table)";
    else v.visit([&](auto&& x) { os << x; });
    return os.str();
  };
  if (const toml::array* a = n->as_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < a->size(); ++i) out += (i ? ", " : "") + scalar(*a->get(i));
    return out + "]";
  }
  return scalar(*n);
}

const std::pair<const std::string, std::string>* TomlReader::change_of(std::string_view key) const {
  // The key itself, a table it lies in, or a key inside it, changed on the command line.
  for (const auto& entry : changed_) {
    const std::string& k = entry.first;
    if (key == k || (key.size() > k.size() && key.substr(0, k.size()) == k && key[k.size()] == '.') ||
        (k.size() > key.size() && std::string_view(k).substr(0, key.size()) == key && k[key.size()] == '.'))
      return &entry;
  }
  return nullptr;
}

std::string TomlReader::where(std::string_view key) const {
  if (const auto* ch = change_of(key)) return file_ + " (--set " + ch->first + "=" + ch->second + ")";
  const int line = line_of(key);
  return line > 0 ? file_ + ":" + std::to_string(line) : file_;
}

Origin TomlReader::origin(std::string_view key) const {
  Origin o;
  o.file = file_;
  const toml::node* n = find(key);
  if (!n) {
    o.line = line_of(key);  // absent: the default, at its nearest enclosing table
    return o;
  }
  if (const auto* ch = change_of(key)) {
    o.kind = Origin::Kind::set;
    o.set_key = ch->first;
    o.set_value = ch->second;
    return o;
  }
  o.kind = Origin::Kind::file;
  o.line = static_cast<int>(n->source().begin.line);
  o.column = static_cast<int>(n->source().begin.column);
  return o;
}

std::string TomlReader::warning(std::string_view key, const std::string& message) const {
  const std::string value = value_text(key);
  return fmt::format("{}: warning: key '{}'{}: {}", where(key), key, value.empty() ? "" : " = " + value, message);
}

void TomlReader::fail(std::string_view key, const std::string& rule) const {
  // A key changed on the command line (or inside a changed table) is named by its --set.
  if (const auto* ch = change_of(key))
    throw InputError(file_ + " (--set " + ch->first + "=" + ch->second + ")", 0, std::string(key), value_text(key),
                     rule);
  throw InputError(file_, line_of(key), std::string(key), value_text(key), rule);
}

double TomlReader::node_number(const toml::node& n, std::string_view key) const {
  double v = 0.0;
  if (const std::string rule = number_problem(n, v); !rule.empty()) fail(key, rule);
  return v;
}

double TomlReader::to_quantity(const toml::node& n, std::string_view key, Dimension d) const {
  if (n.is_integer() || n.is_floating_point()) return node_number(n, key);
  if (!n.is_string())
    fail(key, "expected a " + std::string(dimension_name(d)) + ": a number (SI) or a string like \"6 mm\"");
  try {
    return parse_quantity(n.as_string()->get(), d);
  } catch (const std::invalid_argument& e) {
    fail(key, e.what());
  }
}

const toml::node* TomlReader::take(std::string_view key, bool has_fallback, const std::string& what) {
  const toml::node* n = find(key);
  if (!n) {
    if (has_fallback) return nullptr;
    fail(key, "missing required key (" + what + ")");
  }
  used_.emplace(key);
  return n;
}

double TomlReader::quantity(std::string_view key, Dimension d, std::optional<double> fallback) {
  const toml::node* n = take(key, fallback.has_value(), "a " + std::string(dimension_name(d)));
  return n ? to_quantity(*n, key, d) : *fallback;
}

std::vector<double> TomlReader::quantity_array(std::string_view key, Dimension d) {
  const toml::node* n = take(key, false, "an array of " + std::string(dimension_name(d)) + " values");
  const toml::array* arr = n->as_array();
  if (!arr) fail(key, "expected an array");
  std::vector<double> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const std::string item = std::string(key) + "[" + std::to_string(i) + "]";
    const toml::node& e = *arr->get(i);
    const int line = changed(key) ? 0 : static_cast<int>(e.source().begin.line);
    const std::string where_item = changed(key) ? where(key) : file_;
    if (e.is_integer() || e.is_floating_point()) {
      double v = 0.0;
      if (const std::string rule = number_problem(e, v); !rule.empty()) {
        std::ostringstream os;
        e.visit([&](auto&& value) { os << value; });
        throw InputError(where_item, line, item, os.str(), rule);
      }
      out.push_back(v);
    } else if (e.is_string()) {
      try {
        out.push_back(parse_quantity(e.as_string()->get(), d));
      } catch (const std::invalid_argument& ex) {
        throw InputError(where_item, line, item, '"' + e.as_string()->get() + '"', ex.what());
      }
    } else {
      throw InputError(file_, static_cast<int>(e.source().begin.line), item, "",
                       "expected a number or a string like \"418 MPa\"");
    }
  }
  return out;
}

double TomlReader::number(std::string_view key, std::optional<double> fallback) {
  const toml::node* n = take(key, fallback.has_value(), "a number");
  if (!n) return *fallback;
  if (!(n->is_integer() || n->is_floating_point())) fail(key, "expected a number");
  return node_number(*n, key);
}

long TomlReader::integer(std::string_view key, std::optional<long> fallback) {
  const toml::node* n = take(key, fallback.has_value(), "an integer");
  if (!n) return *fallback;
  if (!n->is_integer()) fail(key, "expected an integer");
  return static_cast<long>(n->as_integer()->get());
}

bool TomlReader::boolean(std::string_view key, std::optional<bool> fallback) {
  const toml::node* n = take(key, fallback.has_value(), "true or false");
  if (!n) return *fallback;
  if (!n->is_boolean()) fail(key, "expected true or false");
  return n->as_boolean()->get();
}

std::string TomlReader::string(std::string_view key, std::optional<std::string> fallback) {
  const toml::node* n = take(key, fallback.has_value(), "a string");
  if (!n) return *fallback;
  if (!n->is_string()) fail(key, "expected a string");
  return n->as_string()->get();
}

std::vector<std::string> TomlReader::string_array(std::string_view key) {
  const toml::node* n = take(key, false, "an array of strings");
  const toml::array* arr = n->as_array();
  if (!arr)
    fail(key,
         "expected an array of strings, written [\"a\", \"b\"] in a case file; --set takes the same or bare "
         "words: KEY=[a, b]");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const toml::node& e = *arr->get(i);
    if (!e.is_string())
      throw InputError(file_, static_cast<int>(e.source().begin.line), std::string(key) + "[" + std::to_string(i) + "]",
                       "", "expected a string");
    out.push_back(e.as_string()->get());
  }
  return out;
}

std::vector<std::string> TomlReader::keys_of(std::string_view table) const {
  std::vector<std::string> out;
  const toml::node* n = find(table);
  if (!n || !n->is_table()) return out;
  for (auto&& [k, v] : *n->as_table()) out.emplace_back(k.str());
  return out;
}

void TomlReader::check_all_used() const {
  // Depth-first over the tables; a leaf (or array) no accessor read is unknown.
  auto walk = [&](auto&& self, const toml::table& t, const std::string& prefix) -> void {
    for (auto&& [k, v] : t) {
      const std::string path = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
      if (const toml::table* sub = v.as_table()) {
        self(self, *sub, path);
      } else if (!used_.contains(path)) {
        if (changed_.contains(path)) fail(path, "unknown key (misspelt, or not used by this version)");
        throw InputError(file_, static_cast<int>(v.source().begin.line), path, value_text(path),
                         "unknown key (misspelt, or not used by this version)");
      }
    }
  };
  walk(walk, root_, "");
}

}  // namespace geartrib::io
