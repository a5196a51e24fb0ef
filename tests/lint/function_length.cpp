// function_length: no function body longer than kMostLines lines in the sources it is given. It reads
// each .cpp and .h with its comments, string and character literals (raw ones too) and preprocessor
// lines blanked out, counts braces, and takes a `{` at namespace or class level that follows a
// parameter list `)` (then perhaps const, noexcept, override, final or `-> T`, or a constructor's
// member initialisers) as a function body, unless the parenthesis belongs to if, for, while, switch
// or catch. A TEST_CASE body is a function; a TEST_SUITE block is not; a lambda is part of the
// function around it. The length of a body is its lines from the `{` to the `}`, both included.
//   function_length ROOT FOLDER...   lists every long function as file:line: name, fails on any
//   function_length --self-test      checks the reader on snippets with known answers
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr int kMostLines = 80;

struct LongFunction {
  std::string file;
  int line = 0;  ///< where its name is
  std::string name;
  int lines = 0;
};

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Replaces text[from, to) by spaces, newlines kept (so offsets and line numbers stay).
void blank(std::string& text, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to && i < text.size(); ++i)
    if (text[i] != '\n') text[i] = ' ';
}

/// The end of the raw string literal whose R is at `r` (just past its closing quote), or npos when
/// `r` does not start one.
std::size_t raw_string_end(const std::string& text, std::size_t r) {
  if (text.compare(r, 2, "R\"") != 0) return std::string::npos;
  std::size_t start = r;
  while (start > 0 && identifier_char(text[start - 1])) --start;
  const std::string_view prefix(text.data() + start, r - start);
  if (!(prefix.empty() || prefix == "u8" || prefix == "u" || prefix == "U" || prefix == "L")) return std::string::npos;
  const std::size_t open = text.find('(', r + 2);
  if (open == std::string::npos) return std::string::npos;
  const std::string close = ")" + text.substr(r + 2, open - r - 2) + "\"";
  const std::size_t end = text.find(close, open + 1);
  return end == std::string::npos ? text.size() : end + close.size();
}

/// The end of the quoted literal that starts at `i` (just past its closing quote).
std::size_t quoted_end(const std::string& text, std::size_t i) {
  std::size_t j = i + 1;
  while (j < text.size() && text[j] != text[i] && text[j] != '\n') j += text[j] == '\\' ? 2 : 1;
  return std::min(j + 1, text.size());
}

/// The end of the preprocessor line that starts at `i`, its continuation lines included.
std::size_t directive_end(const std::string& text, std::size_t i) {
  std::size_t j = i;
  while (j < text.size() && text[j] != '\n') j += text[j] == '\\' ? 2 : 1;
  return std::min(j, text.size());
}

bool line_starts_at(const std::string& text, std::size_t i) {
  std::size_t j = i;
  while (j > 0 && (text[j - 1] == ' ' || text[j - 1] == '\t')) --j;
  return j == 0 || text[j - 1] == '\n';
}

/// `text` with comments, literals and preprocessor lines blanked out.
std::string code_only(std::string text) {
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t end = std::string::npos;
    if (text.compare(i, 2, "//") == 0) {
      end = text.find('\n', i);
    } else if (text.compare(i, 2, "/*") == 0) {
      end = text.find("*/", i + 2);
      end = end == std::string::npos ? text.size() : end + 2;
    } else if (text[i] == 'R') {
      end = raw_string_end(text, i);
    } else if (text[i] == '"' || (text[i] == '\'' && !(i > 0 && identifier_char(text[i - 1])))) {
      end = quoted_end(text, i);
    } else if (text[i] == '#' && line_starts_at(text, i)) {
      end = directive_end(text, i);
    }
    if (end == std::string::npos) {
      ++i;
      continue;
    }
    end = std::min(end, text.size());
    blank(text, i, end);
    i = end;
  }
  return text;
}

/// The words that may stand between a parameter list and its body.
bool trailing_word(std::string_view word) {
  return word == "const" || word == "noexcept" || word == "override" || word == "final" || word == "mutable";
}

/// The first index at or after `i` that is not a space.
std::size_t skip_space_forward(const std::string& code, std::size_t i) {
  while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
  return i;
}

/// Skips back over spaces from `i` (exclusive); the index just past the last non-space before it.
std::size_t skip_space_back(const std::string& code, std::size_t i) {
  while (i > 0 && std::isspace(static_cast<unsigned char>(code[i - 1]))) --i;
  return i;
}

/// The word ending at `end` (exclusive).
std::string_view word_before(const std::string& code, std::size_t end) {
  std::size_t start = end;
  while (start > 0 && identifier_char(code[start - 1])) --start;
  return std::string_view(code).substr(start, end - start);
}

/// The start of the statement the `{` at `brace` ends: just past the previous `;`, `{` or `}`.
std::size_t statement_start(const std::string& code, std::size_t brace) {
  const std::size_t at = code.find_last_of(";{}", brace == 0 ? 0 : brace - 1);
  return at == std::string::npos || brace == 0 ? 0 : at + 1;
}

/// The `)` that ends at `end` (exclusive) once trailing words (const, noexcept, ...) are skipped,
/// or npos.
std::size_t close_before_words(const std::string& code, std::size_t end) {
  end = skip_space_back(code, end);
  for (std::string_view word = word_before(code, end); !word.empty() && trailing_word(word);
       word = word_before(code, end))
    end = skip_space_back(code, end - word.size());
  return end > 0 && code[end - 1] == ')' ? end - 1 : std::string::npos;
}

/// The `)` of the parameter list the `{` at `brace` follows (past trailing words, `-> T`, a
/// constructor's member initialisers), or npos when the brace follows none.
std::size_t parameter_list_end(const std::string& code, std::size_t brace) {
  const std::size_t close = close_before_words(code, brace);
  if (close != std::string::npos) return close;
  // `-> T`: the arrow after the parameter list, with no parenthesis or brace between it and the body.
  const std::size_t arrow = code.rfind("->", brace);
  if (arrow == std::string::npos || arrow < statement_start(code, brace) || code.find_first_of("(){}", arrow) != brace)
    return std::string::npos;
  return close_before_words(code, arrow);
}

/// The name of the call or declarator whose parameter list opens at `open`: the qualified
/// identifier before it, `operator...` included.
std::string name_before(const std::string& code, std::size_t open) {
  std::size_t end = skip_space_back(code, open);
  std::size_t start = end;
  while (start > 0) {
    if (identifier_char(code[start - 1]) || code[start - 1] == '~') {
      --start;
    } else if (start > 1 && code[start - 1] == ':' && code[start - 2] == ':') {
      start -= 2;
    } else {
      break;
    }
  }
  if (start == end) {
    // operator(), operator==, ...: back to the word `operator`.
    const std::size_t op = code.rfind("operator", end);
    if (op != std::string::npos && end - op < 12) return name_before(code, op + 8) + code.substr(op + 8, end - op - 8);
    return "";
  }
  return code.substr(start, end - start);
}

/// The first `(` at parenthesis depth 0 in [from, to): a declarator's parameter list (member
/// initialisers and a trailing return type come after it).
std::size_t first_open(const std::string& code, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to; ++i) {
    if (code[i] == '(') return i;
    if (code[i] == '{' || code[i] == '}') return std::string::npos;
  }
  return std::string::npos;
}

/// The function whose body the `{` at `brace` opens, or "" when it opens no function; `name_at` is
/// set to where its name is.
std::string function_at(const std::string& code, std::size_t brace, std::size_t& name_at) {
  if (parameter_list_end(code, brace) == std::string::npos) return "";
  std::size_t open = first_open(code, statement_start(code, brace), brace);
  if (open == std::string::npos) return "";
  std::string name = name_before(code, open);
  if (name.ends_with("operator") && code[skip_space_forward(code, open + 1)] == ')') {
    // operator()(...): the parameter list is the second pair.
    name += "()";
    open = first_open(code, skip_space_forward(code, open + 1) + 1, brace);
    if (open == std::string::npos) return "";
  }
  static const std::string_view kNotFunctions[] = {"if", "for", "while", "switch", "catch", "TEST_SUITE", "return"};
  if (name.empty() || std::find(std::begin(kNotFunctions), std::end(kNotFunctions), name) != std::end(kNotFunctions))
    return "";
  const std::size_t end = skip_space_back(code, open);
  name_at = end - std::min(end, name.size());
  return name;
}

int line_of(const std::string& text, std::size_t at) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

/// A TEST_CASE is reported with its title, read from the source as written.
std::string shown_name(const std::string& source, const std::string& name, std::size_t name_at) {
  if (name != "TEST_CASE" && name != "SCENARIO") return name;
  const std::size_t quote = source.find('"', name_at);
  if (quote == std::string::npos) return name;
  return name + "(" + source.substr(quote, quoted_end(source, quote) - quote) + ")";
}

/// Every function body in `source` longer than kMostLines lines, `file` naming it.
std::vector<LongFunction> long_functions(const std::string& file, const std::string& source) {
  const std::string code = code_only(source);
  struct Open {
    bool function;
    std::size_t at;
    std::string name;
    std::size_t name_at;
  };
  std::vector<Open> open;
  std::vector<LongFunction> found;
  int function_depth = 0;  // how many of the open braces are function bodies
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (code[i] == '{') {
      std::size_t name_at = 0;
      const std::string name = function_depth == 0 ? function_at(code, i, name_at) : "";
      open.push_back({!name.empty(), i, name, name_at});
      function_depth += name.empty() ? 0 : 1;
    } else if (code[i] == '}' && !open.empty()) {
      const Open body = open.back();
      open.pop_back();
      if (!body.function) continue;
      --function_depth;
      const int lines = line_of(code, i) - line_of(code, body.at) + 1;
      if (lines > kMostLines)
        found.push_back({file, line_of(code, body.name_at), shown_name(source, body.name, body.name_at), lines});
    }
  }
  return found;
}

/// The .cpp and .h files below `root`/`folder`, as paths from `root`, sorted.
std::vector<std::string> sources(const fs::path& root, const std::string& folder) {
  std::vector<std::string> files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root / folder)) {
    const std::string extension = entry.path().extension().string();
    if (entry.is_regular_file() && (extension == ".cpp" || extension == ".h"))
      files.push_back(entry.path().lexically_relative(root).generic_string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Lists the long functions below `root`'s `folders`; 0 when there is none, else 1.
int check(const fs::path& root, const std::vector<std::string>& folders) {
  int failures = 0;
  for (const std::string& folder : folders)
    for (const std::string& file : sources(root, folder))
      for (const LongFunction& f : long_functions(file, read(root / file))) {
        std::printf("%s:%d: %s: %d lines, more than %d\n", f.file.c_str(), f.line, f.name.c_str(), f.lines, kMostLines);
        ++failures;
      }
  if (failures == 0) std::printf("no function longer than %d lines\n", kMostLines);
  return failures == 0 ? 0 : 1;
}

// The self-test: snippets whose long functions are known.

/// A function `name` whose body (brace to brace) is `lines` lines, with `filler` as each inner line.
std::string function_text(const std::string& head, int lines, const std::string& filler = "  ++x;") {
  std::string text = head + " {\n";
  for (int k = 0; k < lines - 2; ++k) text += filler + "\n";
  return text + "}\n";
}

struct SelfTest {
  int failures = 0;
  void expect(const std::string& what, const std::string& source, const std::vector<std::string>& names) {
    std::vector<std::string> got;
    for (const LongFunction& f : long_functions("snippet.cpp", source)) got.push_back(f.name);
    if (got == names) return;
    ++failures;
    std::printf("self-test failed: %s: found", what.c_str());
    for (const std::string& name : got) std::printf(" [%s]", name.c_str());
    std::printf(", expected");
    for (const std::string& name : names) std::printf(" [%s]", name.c_str());
    std::printf("\n");
  }
};

void self_test_lengths(SelfTest& t) {
  t.expect("80 lines", function_text("int f(int x)", 80), {});
  t.expect("81 lines", function_text("int f(int x)", 81), {"f"});
  t.expect("a member, const", "struct A {\n" + function_text("  int A::g() const", 81) + "};\n", {"A::g"});
  t.expect("noexcept and a trailing return type", function_text("auto h() noexcept -> int", 81), {"h"});
  t.expect("member initialisers", function_text("A::A(int a) : a_(a), b_(2)", 81), {"A::A"});
  t.expect("an operator", function_text("bool operator==(const A& a, const A& b)", 81), {"operator=="});
  t.expect("a call operator", function_text("int Call::operator()(int x) const", 81), {"Call::operator()"});
  t.expect("a class is no function",
           "struct B {\n" + function_text("  int f()", 40) + function_text("  int g()", 40) + "  int x = 0;\n};\n", {});
  t.expect("a namespace is no function", "namespace n {\n" + function_text("int f()", 80) + "}\n", {});
  t.expect("two short functions", function_text("int f()", 50) + function_text("int g()", 50), {});
}

void self_test_reading(SelfTest& t) {
  t.expect("braces in comments, strings and characters",
           function_text("int f()", 80, "  s = \"}{\"; c = '{'; // }\n  /* } */"), {"f"});
  t.expect("a raw string with a quote and braces",
           function_text("int f()", 80, "  s = R\"x(}\" )\" {)x\";") + function_text("int g()", 80), {});
  t.expect("a lambda is part of its function",
           function_text("int f()", 70) + function_text("int g()", 60, "  auto l = [](int y) { return y; };"), {});
  t.expect("a lambda's lines count for its function",
           "int f() {\n  auto l = [](int y) {\n" + std::string(80, '\n') + "  };\n}\n", {"f"});
  t.expect("control statements are no functions", function_text("int f()", 40, "  if (x) { ++x; }\n  for (;;) {\n  }"),
           {"f"});
  t.expect("a preprocessor line", "#define OPEN {\n#define CALL(x) f(x) {\n" + function_text("int f()", 80), {});
  const std::string long_case = function_text("  TEST_CASE(\"a (long) one\")", 81);
  t.expect("a TEST_CASE is a function, a TEST_SUITE is not",
           "TEST_SUITE(\"suite\") {\n" + function_text("  TEST_CASE(\"short\")", 80) + long_case + "}\n",
           {"TEST_CASE(\"a (long) one\")"});
}

int self_test() {
  SelfTest t;
  self_test_lengths(t);
  self_test_reading(t);
  if (t.failures == 0) std::printf("self-test passed\n");
  return t.failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "--self-test") return self_test();
  if (args.size() < 2) {
    std::fprintf(stderr, "usage: function_length ROOT FOLDER... | function_length --self-test\n");
    return 2;
  }
  try {
    return check(args[0], std::vector<std::string>(args.begin() + 1, args.end()));
  } catch (const fs::filesystem_error& e) {
    std::fprintf(stderr, "function_length: %s\n", e.what());
    return 2;
  }
}
