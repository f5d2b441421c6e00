#include "shader/loop_guard.h"

#include "core/error.h"

#include <algorithm>
#include <cctype>
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

}  // namespace

GuardedSource guardLoops(const std::string& text, const std::string& shown, int firstId) {
    const std::vector<Token> tokens = tokenize(text);
    GuardedSource out;
    std::vector<Edit> edits;
    auto fail = [&](int line, const std::string& why) {
        throw Error(shown + ":" + std::to_string(line) + ": error: " + why);
    };
    auto word = [&](std::size_t k) { return text.substr(tokens[k].at, tokens[k].size); };
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
    auto guard = [&](std::size_t from, std::size_t to, int line) {
        const int id = firstId + int(out.loopLines.size());
        out.loopLines.push_back(line);
        const std::size_t begin = tokens[from].at + tokens[from].size, end = tokens[to].at;
        const bool empty = from + 1 == to;
        if (!empty && declares(from + 1, to))
            fail(tokens[from + 1].line, "a loop condition that declares a variable cannot be bounded by raylab's loop "
                                        "guard: declare the variable before the loop");
        if (empty) {
            edits.push_back({begin, " rl_loop(true, " + std::to_string(id) + ")"});
        } else {
            // Parenthesised, so a comma expression stays one argument.
            edits.push_back({tokens[from + 1].at, "rl_loop(("});
            edits.push_back({end, "), " + std::to_string(id) + ")"});
        }
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
        // An array size: `float a[100000]`, `float[100000](...)`.
        if (is(text, t, "[") && k + 2 < tokens.size() && tokens[k + 1].number && is(text, tokens[k + 2], "]")) {
            const std::string literal = word(k + 1);
            char* end = nullptr;
            const long long n = std::strtoll(literal.c_str(), &end, 0);
            const bool huge = literal.size() > 9 || n > kMaxArrayElements;
            if (huge && literal.find_first_of(".eE") == std::string::npos)
                fail(t.line, "an array of " + literal + " elements is more memory than a GPU gives one pixel (at "
                                 "most " + std::to_string(kMaxArrayElements) + " elements here): refused before "
                                 "compiling, as it would run out of memory or time depending on the machine");
        }
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
            if (!doStack.empty() && doStack.back().depth == depth) {  // the while of a do-while
                line = doStack.back().line;
                doStack.pop_back();
            }
            if (close == open + 1) continue;  // `while ()`: a syntax error
            guard(open, close, line);
        } else {
            std::vector<std::size_t> semicolons;
            int parens = 0;
            for (std::size_t j = open + 1; j < close; ++j) {
                if (is(text, tokens[j], "(")) ++parens;
                if (is(text, tokens[j], ")")) --parens;
                if (parens == 0 && is(text, tokens[j], ";")) semicolons.push_back(j);
            }
            if (semicolons.size() != 2) continue;  // not a for header: a syntax error the driver reports
            guard(semicolons[0], semicolons[1], t.line);
        }
        k = open;  // the header's tokens are looked at again (arrays), none is a loop
    }
    refuseMacroBombs(text, tokens, shown);
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.at < b.at; });
    out.text.reserve(text.size() + 24 * edits.size());
    std::size_t from = 0;
    for (const Edit& e : edits) {
        out.text.append(text, from, e.at - from);
        out.text += e.text;
        from = e.at;
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
    std::string loop = "a loop";
    if (id >= 1 && id <= int(loops.size())) {
        const SourceLocation& l = loops[std::size_t(id) - 1];
        const std::string file = l.file.substr(l.file.find_last_of('/') + 1);
        loop += " in " + file + ":" + std::to_string(l.line);
    }
    return loop + " ran more than " + std::to_string(kLoopLimit) + " iterations " + where +
           ": on a GPU it would not finish (raylab ends every loop there, so the verdict is the same on every "
           "machine)";
}

}  // namespace rl
