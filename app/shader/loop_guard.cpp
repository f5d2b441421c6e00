#include "shader/loop_guard.h"

#include "core/error.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <limits>
#include <optional>
#include <cstdlib>
#include <map>

namespace rl {

namespace {

struct Token {
    std::size_t at = 0;    // byte offset in the text
    std::size_t size = 0;
    int line = 0;
    bool ident = false;     // identifier or keyword
    bool number = false;    // a literal starting with a digit
    bool directive = false; // inside a preprocessor line
};

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Tokens outside comments, in one pass. A preprocessor line (a '#' first on
// its line, continued by a backslash) marks its tokens as `directive`.
std::vector<Token> tokenize(const std::string& s) {
    std::vector<Token> out;
    int line = 1;
    bool lineStart = true, inDirective = false;
    std::size_t i = 0;
    while (i < s.size()) {
        char c = s[i];
        if (c == '\n') {
            // A backslash before the newline continues a directive.
            std::size_t k = i;
            while (k > 0 && (s[k - 1] == '\r')) --k;
            if (!(inDirective && k > 0 && s[k - 1] == '\\')) inDirective = false;
            ++line;
            ++i;
            lineStart = true;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\\') {
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            std::size_t end = s.find("*/", i + 2);
            end = end == std::string::npos ? s.size() : end + 2;
            line += int(std::count(s.begin() + std::ptrdiff_t(i), s.begin() + std::ptrdiff_t(end), '\n'));
            i = end;
            continue;
        }
        if (lineStart && c == '#') inDirective = true;
        lineStart = false;
        Token t;
        t.at = i;
        t.line = line;
        t.directive = inDirective;
        if (identStart(c)) {
            while (i < s.size() && identChar(s[i])) ++i;
            t.ident = true;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i < s.size() && (identChar(s[i]) || s[i] == '.')) ++i;
            t.number = true;
        } else {
            ++i;
        }
        t.size = i - t.at;
        out.push_back(t);
    }
    return out;
}

bool is(const std::string& s, const Token& t, const char* word) {
    return s.compare(t.at, t.size, word) == 0 && std::char_traits<char>::length(word) == t.size;
}

// Index of the ')' matching the '(' at `open`, or tokens.size().
std::size_t matching(const std::string& s, const std::vector<Token>& tokens, std::size_t open) {
    int depth = 0;
    for (std::size_t k = open; k < tokens.size(); ++k) {
        if (tokens[k].directive) continue;
        if (is(s, tokens[k], "(")) ++depth;
        if (is(s, tokens[k], ")") && --depth == 0) return k;
        if (is(s, tokens[k], "{") || is(s, tokens[k], "}")) return tokens.size();  // not a loop header
    }
    return tokens.size();
}

struct Edit {
    std::size_t at;
    std::string text;
    std::size_t erase = 0;  // characters of the file replaced by `text` from `at`
};

// A file whose object-like macros expand to more than kMaxExpandedTokens
// tokens (`#define A1 A0 A0`, `#define A2 A1 A1`, ...: doubling per line) is
// refused before the driver's preprocessor spends minutes or gigabytes on
// it, which would make the verdict TIMEOUT or CRASH depending on the
// machine. Sizes are computed once per macro, in the order of the
// definitions (a name defined later counts as one token), saturating.
void refuseMacroBombs(const std::string& text, const std::vector<Token>& tokens, const std::string& shown) {
    constexpr double kMaxExpandedTokens = 1e6;  // a real exercise file expands to a few thousand
    std::map<std::string, double> size;          // macro -> tokens it expands to
    std::map<std::string, int> lineOf;
    double total = 0;
    std::string biggest;
    for (std::size_t k = 0; k < tokens.size();) {
        const Token& t = tokens[k];
        const bool define = t.directive && is(text, t, "#") && k + 2 < tokens.size() &&
                            is(text, tokens[k + 1], "define") && tokens[k + 2].ident && tokens[k + 2].directive;
        if (!define) {
            if (!t.directive) {
                auto it = t.ident ? size.find(text.substr(t.at, t.size)) : size.end();
                total = std::min(total + (it == size.end() ? 1.0 : it->second), 2 * kMaxExpandedTokens);
            }
            ++k;
            continue;
        }
        const std::string name = text.substr(tokens[k + 2].at, tokens[k + 2].size);
        std::size_t j = k + 3;
        double n = 0;
        for (; j < tokens.size() && tokens[j].directive && !(is(text, tokens[j], "#") && j > k + 3 &&
                                                              tokens[j].line != tokens[j - 1].line);
             ++j) {
            auto it = tokens[j].ident ? size.find(text.substr(tokens[j].at, tokens[j].size)) : size.end();
            n = std::min(n + (it == size.end() ? 1.0 : it->second), 2 * kMaxExpandedTokens);
        }
        size[name] = std::max(n, 1.0);
        lineOf[name] = t.line;
        if (biggest.empty() || size[name] > size[biggest]) biggest = name;
        k = j;
    }
    if (!biggest.empty() && (size[biggest] >= kMaxExpandedTokens || total >= kMaxExpandedTokens))
        throw Error(shown + ":" + std::to_string(lineOf[biggest]) + ": error: the macro " + biggest +
                    " expands to more than a million tokens (a macro bomb): refused before compiling, as the "
                    "compiler would run out of time or memory depending on the machine");
}


// Constant folding of GLSL int expressions, enough for array sizes: decimal,
// hex and octal literals (a u suffix allowed), names of `const int` /
// `const uint` variables and of object-like macros declared earlier, unary
// + and -, binary + - * / % and parentheses. Iterative (two stacks), values
// saturate at +-2^62, so any input costs time linear in its length.
class ConstFolder {
public:
    ConstFolder(const std::string& text, const std::vector<Token>& tokens) : text_(text), tokens_(tokens) {}

    void define(const std::string& name, std::optional<long long> value) {
        if (value)
            values_[name] = *value;
        else
            values_.erase(name);
    }

    // The value of tokens [from, to), or nullopt when they are not such an expression.
    std::optional<long long> fold(std::size_t from, std::size_t to) const {
        if (from >= to || to - from > 4096) return std::nullopt;
        std::vector<long long> values;
        std::vector<char> ops;  // '(' , binary + - * / % , unary 'n' (minus) 'p' (plus)
        auto prec = [](char op) { return op == 'n' || op == 'p' ? 3 : op == '*' || op == '/' || op == '%' ? 2 : 1; };
        auto apply = [&](char op) -> bool {
            if (op == 'n' || op == 'p') {
                if (values.empty()) return false;
                if (op == 'n') values.back() = -values.back();
                return true;
            }
            if (values.size() < 2) return false;
            const long long b = values.back();
            values.pop_back();
            long long& a = values.back();
            const long double r = op == '+'   ? (long double)a + b
                                  : op == '-' ? (long double)a - b
                                  : op == '*' ? (long double)a * b
                                  : b == 0    ? std::numeric_limits<long double>::quiet_NaN()
                                  : op == '/' ? (long double)(a / b)
                                              : (long double)(a % b);
            if (r != r) return false;
            a = (long long)std::max<long double>(-kSaturate, std::min<long double>(kSaturate, r));
            return true;
        };
        bool expectValue = true;
        for (std::size_t k = from; k < to; ++k) {
            const Token& t = tokens_[k];
            const std::string w = text_.substr(t.at, t.size);
            if (expectValue) {
                if (t.number) {
                    std::string digits = w;
                    if (!digits.empty() && (digits.back() == 'u' || digits.back() == 'U')) digits.pop_back();
                    if (digits.find_first_of(".eE") != std::string::npos && digits.compare(0, 2, "0x") != 0 &&
                        digits.compare(0, 2, "0X") != 0)
                        return std::nullopt;  // a float: no array size
                    char* end = nullptr;
                    errno = 0;
                    unsigned long long v = std::strtoull(digits.c_str(), &end, 0);
                    if (end == nullptr || *end != '\0') return std::nullopt;
                    values.push_back(errno == ERANGE || v > (unsigned long long)kSaturate ? (long long)kSaturate
                                                                                        : (long long)v);
                    expectValue = false;
                } else if (t.ident) {
                    auto it = values_.find(w);
                    if (it == values_.end()) return std::nullopt;
                    values.push_back(it->second);
                    expectValue = false;
                } else if (w == "(") {
                    ops.push_back('(');
                } else if (w == "-" || w == "+") {
                    ops.push_back(w == "-" ? 'n' : 'p');
                } else {
                    return std::nullopt;
                }
            } else {
                if (w == ")") {
                    while (!ops.empty() && ops.back() != '(')
                        if (!apply(ops.back()) || (ops.pop_back(), false)) return std::nullopt;
                    if (ops.empty()) return std::nullopt;
                    ops.pop_back();
                } else if (w.size() == 1 && std::string("+-*/%").find(w[0]) != std::string::npos) {
                    while (!ops.empty() && ops.back() != '(' && prec(ops.back()) >= prec(w[0])) {
                        if (!apply(ops.back())) return std::nullopt;
                        ops.pop_back();
                    }
                    ops.push_back(w[0]);
                    expectValue = true;
                } else {
                    return std::nullopt;
                }
            }
        }
        if (expectValue) return std::nullopt;
        while (!ops.empty()) {
            if (ops.back() == '(' || !apply(ops.back())) return std::nullopt;
            ops.pop_back();
        }
        if (values.size() != 1) return std::nullopt;
        return values.back();
    }

    static constexpr long double kSaturate = 4611686018427387904.0L;  // 2^62

private:
    const std::string& text_;
    const std::vector<Token>& tokens_;
    std::map<std::string, long long> values_;
};

// Arrays bigger than kMaxArrayElements, however their size is written:
// `float a[100000]`, `const int N = 50000000; float a[N];`, `#define N ...`,
// `float a[7000 * 7000]`, `float a[64][128]` (the product), and structs:
// `struct S { float a[4000]; float b[4000]; };` (the sum of its members) and
// `S s[100]` (the struct's size times the count). Sizes that do not fold are
// left to the driver, which requires a constant expression anyway.
void refuseHugeArrays(const std::string& text, const std::vector<Token>& tokens, const std::string& shown) {
    ConstFolder folder(text, tokens);
    std::map<std::string, long long> structSize;  // elements one value of the struct holds
    auto word = [&](std::size_t k) { return text.substr(tokens[k].at, tokens[k].size); };
    auto is = [&](std::size_t k, const char* w) { return k < tokens.size() && rl::is(text, tokens[k], w); };
    auto fail = [&](int line, const std::string& what, long long n) {
        throw Error(shown + ":" + std::to_string(line) + ": error: " + what + " " + std::to_string(n) +
                    " elements is more memory than a GPU gives one pixel (at most " + std::to_string(kMaxArrayElements) +
                    " elements here): refused before compiling, as it would run out of memory or time depending on "
                    "the machine");
    };
    // The ']' that closes the '[' at k (same line or not), or tokens.size().
    auto closeOf = [&](std::size_t k) {
        int depth = 0;
        for (std::size_t j = k; j < tokens.size(); ++j) {
            if (is(j, "[")) ++depth;
            if (is(j, "]") && --depth == 0) return j;
            if (is(j, ";") || is(j, "{") || is(j, "}")) break;
        }
        return tokens.size();
    };
    // The dimensions starting at the '[' at k: their product (unknown ones count 1), and where they end.
    auto dims = [&](std::size_t k, std::size_t& after, std::string& written) {
        long double product = 1;
        after = k;
        written.clear();
        while (is(after, "[")) {
            const std::size_t close = closeOf(after);
            if (close >= tokens.size()) break;
            std::optional<long long> n = folder.fold(after + 1, close);
            if (n && *n > 0) product *= (long double)*n;
            written += text.substr(tokens[after].at, tokens[close].at + 1 - tokens[after].at);
            after = close + 1;
        }
        return (long long)std::min<long double>(product, ConstFolder::kSaturate);
    };
    struct Open {
        std::string name;
        int depthBefore;  // brace depth outside its body
        long double total = 0;
        int line = 0;
    };
    std::vector<Open> structs;  // struct bodies being read
    int depth = 0;
    std::string memberType;     // inside a struct: the type of the member being declared
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const Token& t = tokens[k];
        if (t.directive) {
            if (is(k, "#") && is(k + 1, "define") && k + 2 < tokens.size() && tokens[k + 2].ident &&
                tokens[k + 2].directive) {
                const std::string name = word(k + 2);
                std::size_t end = k + 3;
                while (end < tokens.size() && tokens[end].directive && !(is(end, "#") && tokens[end].line != t.line))
                    ++end;
                const bool functionLike = is(k + 3, "(") && tokens[k + 3].at == tokens[k + 2].at + tokens[k + 2].size;
                folder.define(name, functionLike ? std::nullopt : folder.fold(k + 3, end));
                k = end - 1;
            }
            continue;
        }
        // `const int N = expr;` (qualifiers allowed): N is known from here on.
        if (is(k, "const")) {
            std::size_t j = k + 1;
            while (is(j, "highp") || is(j, "mediump") || is(j, "lowp")) ++j;
            if ((is(j, "int") || is(j, "uint")) && j + 2 < tokens.size() && tokens[j + 1].ident && is(j + 2, "=")) {
                std::size_t end = j + 3;
                int parens = 0;
                for (; end < tokens.size() && !(parens == 0 && (is(end, ";") || is(end, ","))); ++end)
                    parens += is(end, "(") ? 1 : is(end, ")") ? -1 : 0;
                folder.define(word(j + 1), folder.fold(j + 3, end));
            }
        }
        if (is(k, "struct") && k + 2 < tokens.size() && tokens[k + 1].ident && is(k + 2, "{")) {
            structs.push_back({word(k + 1), depth, 0, t.line});
            memberType.clear();
            ++depth;
            k += 2;
            continue;
        }
        if (is(k, "{")) ++depth;
        if (is(k, "}")) {
            --depth;
            if (!structs.empty() && depth == structs.back().depthBefore) {
                Open s = structs.back();
                structs.pop_back();
                const long long n = (long long)std::min<long double>(std::max<long double>(s.total, 1), ConstFolder::kSaturate);
                if (n > kMaxArrayElements) fail(s.line, "the struct " + s.name + " holds", n);
                structSize[s.name] = n;
            }
            continue;
        }
        if (!structs.empty()) {
            // A member: `type name[dims], name2;` (or `type[dims] name;`).
            if (is(k, ";")) {
                memberType.clear();
            } else if (t.ident && memberType.empty() && !is(k, "highp") && !is(k, "mediump") && !is(k, "lowp") &&
                       !is(k, "precise") && !is(k, "invariant")) {
                memberType = word(k);
                std::size_t after = k + 1;
                std::string written;
                long long typeDims = dims(k + 1, after, written);
                auto sizeOfType = structSize.count(memberType) ? structSize[memberType] : 1;
                // Each declarator up to ';'.
                std::size_t j = after;
                while (j < tokens.size() && !is(j, ";") && !is(j, "}")) {
                    if (tokens[j].ident) {
                        std::size_t end = j + 1;
                        long long n = dims(j + 1, end, written);
                        structs.back().total += (long double)n * typeDims * sizeOfType;
                        j = end;
                    } else {
                        ++j;
                    }
                }
                k = j - 1;
            }
            continue;
        }
        if (!is(k, "[")) continue;
        // Outside structs: any size or index that folds; its chain of dimensions; a struct type's size.
        std::size_t after = k;
        std::string written;
        const std::size_t close = closeOf(k);
        if (close >= tokens.size()) continue;
        std::optional<long long> one = folder.fold(k + 1, close);
        long long n = dims(k, after, written);
        long long per = 1;
        if (k >= 1 && tokens[k - 1].ident) {
            // `S name[...]` or `S[...] name`.
            const std::string before = word(k - 1);
            if (structSize.count(before))
                per = structSize[before];
            else if (k >= 2 && tokens[k - 2].ident && structSize.count(word(k - 2)))
                per = structSize[word(k - 2)];
        }
        const long double total = (long double)n * per;
        if ((one && *one > kMaxArrayElements) || total > kMaxArrayElements) {
            const bool literal = close == k + 2 && tokens[k + 1].number && after == close + 1 && per == 1;
            if (literal) {
                const std::string lit = word(k + 1);
                throw Error(shown + ":" + std::to_string(t.line) + ": error: an array of " + lit +
                            " elements is more memory than a GPU gives one pixel (at most " +
                            std::to_string(kMaxArrayElements) +
                            " elements here): refused before compiling, as it would run out of memory or time depending "
                            "on the machine");
            }
            fail(t.line, "an array " + written + (per > 1 ? " of a struct of " + std::to_string(per) + " elements" : "") +
                             " of",
                 (long long)std::min<long double>(std::max<long double>(total, one ? (long double)*one : 0),
                                                  ConstFolder::kSaturate));
        }
        k = after - 1;
    }
}
}  // namespace

GuardedSource guardLoops(const std::string& text, const std::string& shown, int firstId) {
    const std::vector<Token> tokens = tokenize(text);
    GuardedSource out;
    std::vector<Edit> edits;
    auto fail = [&](int line, const std::string& why) {
        throw Error(shown + ":" + std::to_string(line) + ": error: " + why);
    };
    // A condition that declares a variable (`bool b = ...`) cannot be passed to rl_loop.
    auto declares = [&](std::size_t from, std::size_t to) {
        std::size_t k = from;
        while (k < to && tokens[k].ident &&
               (is(text, tokens[k], "const") || is(text, tokens[k], "highp") || is(text, tokens[k], "mediump") ||
                is(text, tokens[k], "lowp")))
            ++k;
        return k + 2 < to && tokens[k].ident && tokens[k + 1].ident && is(text, tokens[k + 2], "=");
    };
    // Wraps the condition between tokens (from, to) exclusive: `rl_loop((cond), ID)`.
    // The text between tokens (from, to) exclusive, and whether it can be
    // copied onto another line unchanged: one line, no comment.
    auto between = [&](std::size_t from, std::size_t to) {
        const std::size_t begin = tokens[from].at + tokens[from].size, end = tokens[to].at;
        return text.substr(begin, end - begin);
    };
    auto copyable = [](const std::string& part) {
        return part.find('\n') == std::string::npos && part.find("//") == std::string::npos &&
               part.find("/*") == std::string::npos;
    };
    // The loop's condition as the guard asks it: `rl_loop((cond), ID)`.
    auto guarded = [&](const std::string& cond, int id) {
        const bool empty = cond.find_first_not_of(" \t\r\f\v") == std::string::npos;
        return empty ? "rl_loop(true, " + std::to_string(id) + ")" : "rl_loop((" + cond + "), " + std::to_string(id) + ")";
    };
    // The condition between tokens (from, to) exclusive, checked; the loop's ID.
    auto newLoop = [&](std::size_t from, std::size_t to, int line) {
        const int id = firstId + int(out.loopLines.size());
        out.loopLines.push_back(line);
        if (from + 1 != to && declares(from + 1, to))
            fail(tokens[from + 1].line, "a loop condition that declares a variable cannot be bounded by raylab's loop "
                                        "guard: declare the variable before the loop");
        return id;
    };
    // Wraps the condition between tokens (from, to) exclusive: `rl_loop((cond), ID)`.
    auto guard = [&](std::size_t from, std::size_t to, int line) {
        const int id = newLoop(from, to, line);
        const std::size_t begin = tokens[from].at + tokens[from].size, end = tokens[to].at;
        const bool empty = from + 1 == to;
        if (empty) {
            edits.push_back({begin, " rl_loop(true, " + std::to_string(id) + ")"});
        } else {
            // Parenthesised, so a comma expression stays one argument.
            edits.push_back({tokens[from + 1].at, "rl_loop(("});
            edits.push_back({end, "), " + std::to_string(id) + ")"});
        }
    };
    // The `}` closing the body that starts with the `{` at token `open`, or
    // tokens.size() where the body holds a directive or does not close.
    auto bodyEnd = [&](std::size_t open) {
        int depth = 0;
        for (std::size_t k = open; k < tokens.size(); ++k) {
            if (tokens[k].directive) return tokens.size();
            if (is(text, tokens[k], "{")) ++depth;
            if (is(text, tokens[k], "}") && --depth == 0) return k;
        }
        return tokens.size();
    };
    // A loop whose body is a block, its condition and step on their lines, is
    // also turned to test its condition at the end, the way compilers rotate
    // loops:
    //     for (init; cond; step) { body }
    //         ->  { init; if (rl_loop((cond), ID)) do { body } while (((step), rl_loop((cond), ID))); }
    //     while (cond) { body }
    //         ->  if (rl_loop((cond), ID)) do { body } while (rl_loop((cond), ID));
    // The same tests of the condition, in the same order (a `continue` goes
    // to the step and the test), the same lines. llvmpipe tests a loop's mask
    // at the end of its body, so a loop that tests at the top runs its body
    // once more with every pixel masked off after the last test fails:
    // exercise 09's bounce loop, the whole ray tracer (docs/performance.md).
    // Returns false where the loop is not of that form (then guard() alone).
    // A for loop that cannot run away needs no guard, only its count in the
    // invocation's total (rl_counted: the guards of the loops around it see
    // it): `for (int i = A; i < B; ++i)` (or `<=`, `i++`, `i += 1`) with A an
    // integer literal, B an integer literal of at most kUnguardedBound or
    // maxBounces() (at most kMaxBounces), i neither assigned in the body nor
    // handed to a function (which could take it as `out`) nor declared again
    // there, and no loop in the body (so no two such loops multiply).
    // Exercise 09's bounce loop is one: its guard cost 5% of a frame
    // (docs/performance.md). Tokens: `open` the header's `(`, `semi1`,
    // `semi2` its semicolons, `close` its `)`, `end` the body's `}`.
    auto bounded = [&](std::size_t open, std::size_t semi1, std::size_t semi2, std::size_t close, std::size_t end) {
        auto tok = [&](std::size_t k, const char* word) { return k < tokens.size() && is(text, tokens[k], word); };
        auto literalAtMost = [&](std::size_t k, long most) {
            if (k >= tokens.size() || !tokens[k].number) return false;
            const std::string digits = text.substr(tokens[k].at, tokens[k].size);
            if (digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
            return std::stol(digits) <= most;
        };
        // int NAME = LITERAL ;
        if (!(semi1 == open + 5 && tok(open + 1, "int") && tokens[open + 2].ident && tok(open + 3, "=") &&
              literalAtMost(open + 4, kUnguardedBound)))
            return false;
        const std::string name = text.substr(tokens[open + 2].at, tokens[open + 2].size);
        auto isName = [&](std::size_t k) { return k < tokens.size() && tokens[k].ident && is(text, tokens[k], name.c_str()); };
        // NAME < BOUND or NAME <= BOUND
        std::size_t k = semi1 + 1;
        if (!isName(k) || !tok(k + 1, "<")) return false;
        k += tok(k + 2, "=") ? 3 : 2;
        const bool limitOk = (k + 1 == semi2 && literalAtMost(k, kUnguardedBound)) ||
                             (k + 3 == semi2 && tok(k, "maxBounces") && tok(k + 1, "(") && tok(k + 2, ")"));
        if (!limitOk) return false;
        // ++NAME, NAME++ or NAME += 1
        const std::size_t n = close - semi2 - 1;
        const bool stepOk = (n == 3 && tok(semi2 + 1, "+") && tok(semi2 + 2, "+") && isName(semi2 + 3)) ||
                            (n == 3 && isName(semi2 + 1) && tok(semi2 + 2, "+") && tok(semi2 + 3, "+")) ||
                            (n == 4 && isName(semi2 + 1) && tok(semi2 + 2, "+") && tok(semi2 + 3, "=") && tok(semi2 + 4, "1"));
        if (!stepOk) return false;
        for (std::size_t j = close + 1; j < end; ++j) {
            if (tok(j, "for") || tok(j, "while") || tok(j, "do")) return false;
            if (!isName(j)) continue;
            const bool assigned = (j + 1 < end && (tok(j + 1, "=") ? !tok(j + 2, "=") : false)) ||
                                  (j + 2 < end && tokens[j + 2].at == tokens[j + 1].at + 1 && tok(j + 2, "=") &&
                                   !tok(j + 1, "=") && !tok(j + 1, "<") && !tok(j + 1, ">") && !tok(j + 1, "!")) ||
                                  (tok(j + 1, "+") && tok(j + 2, "+")) || (tok(j + 1, "-") && tok(j + 2, "-")) ||
                                  (j >= 2 && ((tok(j - 1, "+") && tok(j - 2, "+")) || (tok(j - 1, "-") && tok(j - 2, "-"))));
            const bool argument = (tok(j - 1, "(") || tok(j - 1, ",")) && (tok(j + 1, ")") || tok(j + 1, ","));
            const bool declared = j > 0 && tokens[j - 1].ident && !tok(j - 1, "return");
            if (assigned || argument || declared) return false;
        }
        return true;
    };
    // condFrom, condTo: the tokens around the condition (the for's two `;`,
    // or the while's parentheses).
    auto rotate = [&](const Token& keyword, std::size_t open, std::size_t close, std::size_t condFrom,
                      std::size_t condTo, bool isFor, int line) {
        if (close + 1 >= tokens.size() || !is(text, tokens[close + 1], "{")) return false;
        const std::size_t end = bodyEnd(close + 1);
        if (end >= tokens.size()) return false;
        const std::string cond = between(condFrom, condTo);
        const std::string step = isFor ? between(condTo, close) : "";
        if (!copyable(cond) || !copyable(step) || !copyable(between(condFrom, close))) return false;
        const bool safe = isFor && bounded(open, condFrom, condTo, close, end);
        const std::string test = safe ? "rl_counted(" + cond + ")" : guarded(cond, newLoop(condFrom, condTo, line));
        const std::size_t afterHeader = tokens[close].at + 1;
        if (isFor) {  // `for (` -> `{ `, `cond; step)` -> ` if (test) do`
            edits.push_back({keyword.at, "{ ", tokens[open].at + 1 - keyword.at});
            const std::size_t afterInit = tokens[condFrom].at + 1;
            edits.push_back({afterInit, " if (" + test + ") do", afterHeader - afterInit});
            const bool noStep = step.find_first_not_of(" \t\r\f\v") == std::string::npos;
            edits.push_back({tokens[end].at + 1, " while (" + (noStep ? test : "((" + step + "), " + test + ")") + "); }"});
        } else {  // a while loop
            edits.push_back({keyword.at, "if (" + test + ") do", afterHeader - keyword.at});
            edits.push_back({tokens[end].at + 1, " while (" + test + ");"});
        }
        return true;
    };
    struct Do {
        int line;
        int depth;
    };
    std::vector<Do> doStack;  // do-while loops whose `while` is still to come
    int depth = 0;            // brace depth
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const Token& t = tokens[k];
        if (t.directive) {
            if (t.ident && (is(text, t, "for") || is(text, t, "while") || is(text, t, "do")))
                fail(t.line, "a loop inside a #define cannot be bounded by raylab's loop guard (on a GPU a loop "
                             "that never ends hangs the machine): write the loop out in the function");
            continue;
        }
        if (is(text, t, "{")) ++depth;
        if (is(text, t, "}")) --depth;
        if (!t.ident) continue;
        if (is(text, t, "do")) {
            doStack.push_back({t.line, depth});
            continue;
        }
        const bool isFor = is(text, t, "for"), isWhile = is(text, t, "while");
        if (!isFor && !isWhile) continue;
        if (k + 1 >= tokens.size() || !is(text, tokens[k + 1], "(")) continue;  // the driver reports it
        const std::size_t open = k + 1, close = matching(text, tokens, open);
        if (close >= tokens.size()) continue;  // unbalanced: a syntax error the driver reports
        if (isWhile) {
            int line = t.line;
            bool endOfDo = false;
            if (!doStack.empty() && doStack.back().depth == depth) {  // the while of a do-while
                line = doStack.back().line;
                doStack.pop_back();
                endOfDo = true;
            }
            if (close == open + 1) continue;  // `while ()`: a syntax error
            if (endOfDo || !rotate(t, open, close, open, close, false, line)) guard(open, close, line);
        } else {
            std::vector<std::size_t> semicolons;
            int parens = 0;
            for (std::size_t j = open + 1; j < close; ++j) {
                if (is(text, tokens[j], "(")) ++parens;
                if (is(text, tokens[j], ")")) --parens;
                if (parens == 0 && is(text, tokens[j], ";")) semicolons.push_back(j);
            }
            if (semicolons.size() != 2) continue;  // not a for header: a syntax error the driver reports
            if (!rotate(t, open, close, semicolons[0], semicolons[1], true, t.line))
                guard(semicolons[0], semicolons[1], t.line);
        }
        k = open;  // the header's tokens are looked at again (arrays), none is a loop
    }
    refuseMacroBombs(text, tokens, shown);
    refuseHugeArrays(text, tokens, shown);
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.at < b.at; });
    out.text.reserve(text.size() + 24 * edits.size());
    std::size_t from = 0;
    for (const Edit& e : edits) {
        out.text.append(text, from, e.at - from);
        out.text += e.text;
        from = e.at + e.erase;
    }
    out.text.append(text, from, std::string::npos);
    return out;
}

int trippedLoop(const std::vector<float>& alpha) {
    int first = 0;
    for (float a : alpha)
        if (a < 0 && a > -1e9f) {
            const int id = int(-a + 0.5f);
            if (id > 0 && (first == 0 || id < first)) first = id;
        }
    return first;
}

int trippedLoopInFramebuffer(GLuint framebuffer, int attachment, int width, int height) {
    std::vector<float> pixels(std::size_t(width) * std::size_t(height) * 4);
    gl::BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl::ReadBuffer(GL_COLOR_ATTACHMENT0 + GLenum(attachment));
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::ReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data());
    std::vector<float> alpha(std::size_t(width) * std::size_t(height));
    for (std::size_t k = 0; k < alpha.size(); ++k) alpha[k] = pixels[4 * k + 3];
    return trippedLoop(alpha);
}

void explainLoopGuard(ShaderDiagnostic& d) {
    if (d.message.find("rl_loop") == std::string::npos) return;
    d.message = "a loop's condition must be a bool (GLSL converts no number to bool: write `while (true)` or "
                "`i != 0`, not `while (1)` or `i`)";
}

std::string loopTimeoutMessage(const std::vector<SourceLocation>& loops, int id, const std::string& where) {
    const bool total = id > kLoopTotalFlag;
    if (total) id -= kLoopTotalFlag;
    std::string at;
    if (id >= 1 && id <= int(loops.size())) {
        const SourceLocation& l = loops[std::size_t(id) - 1];
        const std::string file = l.file.substr(l.file.find_last_of('/') + 1);
        at = file + ":" + std::to_string(l.line);
    }
    const std::string end = ": on a GPU it would not finish (raylab ends every loop there, so the verdict is the same on "
                            "every machine)";
    if (total)
        return "the loops of the exercise files ran more than " + std::to_string(kLoopTotalLimit) +
               " iterations in all " + where + (at.empty() ? "" : ", the last one tested being the loop in " + at) +
               " (every run of a loop ended within " + std::to_string(kLoopLimit) +
               ": a loop run too many times, or an outer loop that never ends)" + end;
    return (at.empty() ? std::string("a loop") : "a loop in " + at) + " ran more than " + std::to_string(kLoopLimit) +
           " iterations " + where + " in one run, without its condition becoming false" + end;
}

}  // namespace rl
