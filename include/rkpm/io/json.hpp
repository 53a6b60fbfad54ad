#pragma once
// rkpm::io::json: a small ordered JSON value for the per-run summary (docs/method.md section 9.4:
// case, policies, particle counts, steps, wall time, key results, energy error). Object keys
// keep insertion order so summaries read in the order they were built. Numbers are doubles,
// written as the shortest text that reads back to the same double; NaN and infinities have
// no JSON form and are written as null. No parser: summaries are written, not read.

#include <cmath>
#include <concepts>
#include <cstddef>
#include <filesystem>
#include <iterator>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include <rkpm/core/error.hpp>
#include <rkpm/io/files.hpp>

namespace rkpm::io {

class json {
 public:
  using array_type = std::vector<json>;
  // (key, value) in insertion order; a linear lookup is fine for summaries of tens of keys.
  using object_type = std::vector<std::pair<std::string, json>>;

  json() = default;
  json(std::nullptr_t) {}
  json(bool b) : value_(b) {}
  // Any arithmetic type except bool is a number (integers above 2^53 lose digits, as in JSON
  // readers that use doubles).
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::same_as<T, bool>)
  json(T x) : value_(static_cast<double>(x)) {}
  json(const char* s) : value_(std::string(s)) {}
  json(std::string s) : value_(std::move(s)) {}
  json(std::string_view s) : value_(std::string(s)) {}
  // A list of numbers, strings, ... becomes an array.
  template <class T>
    requires std::constructible_from<json, const T&>
  json(const std::vector<T>& items) : value_(array_type{}) {
    auto& a = std::get<array_type>(value_);
    a.reserve(items.size());
    for (const auto& x : items) a.emplace_back(x);
  }

  static json array() { json j; j.value_ = array_type{}; return j; }
  static json object() { json j; j.value_ = object_type{}; return j; }

  bool is_null() const { return std::holds_alternative<std::nullptr_t>(value_); }
  bool is_bool() const { return std::holds_alternative<bool>(value_); }
  bool is_number() const { return std::holds_alternative<double>(value_); }
  bool is_string() const { return std::holds_alternative<std::string>(value_); }
  bool is_array() const { return std::holds_alternative<array_type>(value_); }
  bool is_object() const { return std::holds_alternative<object_type>(value_); }

  bool as_bool() const { return get<bool>("a bool"); }
  double as_number() const { return get<double>("a number"); }
  const std::string& as_string() const { return get<std::string>("a string"); }

  // Number of array items or object members (0 for anything else).
  std::size_t size() const {
    if (is_array()) return std::get<array_type>(value_).size();
    if (is_object()) return std::get<object_type>(value_).size();
    return 0;
  }

  // Object member access; a null value becomes an empty object first, a missing key is
  // appended (after the existing keys) as null.
  json& operator[](std::string_view key) {
    if (is_null()) value_ = object_type{};
    if (!is_object()) fail("json: operator[](\"{}\") on a {}; use it on an object or null", key, kind());
    auto& members = std::get<object_type>(value_);
    for (auto& m : members)
      if (m.first == key) return m.second;
    members.emplace_back(std::string(key), json{});
    return members.back().second;
  }
  json& operator[](const char* key) { return (*this)[std::string_view(key)]; }
  // Read-only member lookup; throws if absent.
  const json& at(std::string_view key) const {
    for (const auto& m : get<object_type>("an object"))
      if (m.first == key) return m.second;
    fail("json: no member \"{}\"; check the key or add it first", key);
  }
  bool contains(std::string_view key) const {
    if (!is_object()) return false;
    for (const auto& m : std::get<object_type>(value_))
      if (m.first == key) return true;
    return false;
  }
  const object_type& members() const { return get<object_type>("an object"); }

  // Array access; a null value becomes an empty array first.
  json& push_back(json item) {
    if (is_null()) value_ = array_type{};
    if (!is_array()) fail("json: push_back on a {}; use it on an array or null", kind());
    auto& a = std::get<array_type>(value_);
    a.push_back(std::move(item));
    return a.back();
  }
  // Array item access. A template on the integer type so that a[0] is an exact match and
  // never taken for a null key pointer.
  template <std::integral I>
    requires(!std::same_as<I, bool>)
  const json& operator[](I i) const {
    const auto& a = get<array_type>("an array");
    if (i < 0 || static_cast<std::size_t>(i) >= a.size())
      fail("json: index {} out of range for an array of {} items", i, a.size());
    return a[static_cast<std::size_t>(i)];
  }
  template <std::integral I>
    requires(!std::same_as<I, bool>)
  json& operator[](I i) {
    return const_cast<json&>(std::as_const(*this)[i]);
  }

  // indent < 0: one line; indent >= 0: pretty-printed with that many spaces per level.
  std::string dump(int indent = 2) const {
    std::string out;
    write(out, indent, 0);
    return out;
  }

  // JSON string literal for `s` (quotes included). UTF-8 is passed through unchanged; control
  // characters, quote and backslash are escaped as RFC 8259 requires.
  static std::string quote(std::string_view s) {
    std::string out;
    append_quoted(out, s);
    return out;
  }

  // Shortest round-trip text of x ("-0.0" for negative zero), or "null" when x is not finite.
  static std::string number_text(double x) {
    if (!std::isfinite(x)) return "null";
    // "-0" is valid JSON but common readers (Python) take it as the integer 0 and lose the sign.
    if (x == 0 && std::signbit(x)) return "-0.0";
    return fmt::format("{}", x);
  }

 private:
  template <class T>
  const T& get(const char* what) const {
    if (const T* p = std::get_if<T>(&value_)) return *p;
    fail("json: value is a {}, not {}; check the summary layout", kind(), what);
  }

  const char* kind() const {
    constexpr const char* names[] = {"null", "bool", "number", "string", "array", "object"};
    return names[value_.index()];
  }

  static void append_quoted(std::string& out, std::string_view s) {
    out += '"';
    for (unsigned char c : s) {
      switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default:
          if (c < 0x20)
            fmt::format_to(std::back_inserter(out), "\\u{:04x}", static_cast<unsigned>(c));
          else
            out += static_cast<char>(c);
      }
    }
    out += '"';
  }

  static void newline(std::string& out, int indent, int level) {
    if (indent < 0) return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent) * static_cast<std::size_t>(level), ' ');
  }

  void write(std::string& out, int indent, int level) const {
    switch (value_.index()) {
      case 0: out += "null"; break;
      case 1: out += std::get<bool>(value_) ? "true" : "false"; break;
      case 2: out += number_text(std::get<double>(value_)); break;
      case 3: append_quoted(out, std::get<std::string>(value_)); break;
      case 4: {
        const auto& a = std::get<array_type>(value_);
        if (a.empty()) { out += "[]"; break; }
        out += '[';
        for (std::size_t i = 0; i < a.size(); ++i) {
          if (i) out += ',';
          newline(out, indent, level + 1);
          a[i].write(out, indent, level + 1);
        }
        newline(out, indent, level);
        out += ']';
        break;
      }
      case 5: {
        const auto& o = std::get<object_type>(value_);
        if (o.empty()) { out += "{}"; break; }
        out += '{';
        for (std::size_t i = 0; i < o.size(); ++i) {
          if (i) out += ',';
          newline(out, indent, level + 1);
          append_quoted(out, o[i].first);
          out += indent < 0 ? ":" : ": ";
          o[i].second.write(out, indent, level + 1);
        }
        newline(out, indent, level);
        out += '}';
        break;
      }
    }
  }

  std::variant<std::nullptr_t, bool, double, std::string, array_type, object_type> value_{nullptr};
};

// Writes `value` to `path` (parent directories created, file replaced atomically), ending
// with a newline.
inline void write_json(const std::filesystem::path& path, const json& value, int indent = 2) {
  replace_file(path, value.dump(indent) + '\n');
}

}  // namespace rkpm::io
