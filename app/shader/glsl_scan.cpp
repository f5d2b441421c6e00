#include "shader/glsl_scan.h"

#include <algorithm>
#include <cctype>

namespace rl {

namespace {

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

struct Token {
    std::string_view text;
    int line = 0;
    bool ident = false;
};

// Qualifiers that come before a type or a name and are neither.
bool isQualifier(std::string_view w) {
    static const std::string_view list[] = {"const",  "uniform",  "in",     "out",       "inout",         "attribute",
                                            "varying", "flat",    "smooth", "noperspective", "centroid", "highp",
                                            "mediump", "lowp",    "precise", "invariant", "buffer",       "shared",
                                            "layout",  "precision"};
    return std::find(std::begin(list), std::end(list), w) != std::end(list);
}

std::string join(const std::vector<Token>& tokens, std::size_t from, std::size_t to) {
    std::string out;
    for (std::size_t k = from; k < to; ++k) {
        bool glue = !out.empty() && tokens[k].ident && (identChar(out.back()));
        out += (glue ? " " : "") + std::string(tokens[k].text);
    }
    return out;
}

// Skips "layout ( ... )" and precision qualifiers at the start; returns the first other token.
std::size_t skipLeadingQualifiers(const std::vector<Token>& s) {
    std::size_t k = 0;
    while (k < s.size()) {
        if (s[k].text == "layout" && k + 1 < s.size() && s[k + 1].text == "(") {
            int depth = 0;
            for (++k; k < s.size(); ++k) {
                if (s[k].text == "(") ++depth;
                if (s[k].text == ")" && --depth == 0) break;
            }
            ++k;
        } else if (s[k].ident && isQualifier(s[k].text) && s[k].text != "precision") {
            ++k;
        } else {
            break;
        }
    }
    return k;
}

// One parameter "const in vec3 n" -> type "vec3", name "n"; "out float[3] a" -> "out float[3]".
void parseParameter(const std::vector<Token>& s, std::size_t from, std::size_t to, GlslFunction& f) {
    std::string direction;
    std::vector<Token> rest;
    for (std::size_t k = from; k < to; ++k) {
        std::string_view w = s[k].text;
        if (w == "out" || w == "inout") direction = std::string(w) + " ";
        else if (s[k].ident && isQualifier(w)) continue;
        else rest.push_back(s[k]);
    }
    if (rest.empty()) return;
    if (rest.size() == 1 && rest[0].text == "void" && f.paramTypes.empty()) return;
    // type [brackets] [name [brackets]]
    std::size_t k = 1;
    std::string type(rest[0].text);
    while (k < rest.size() && !rest[k].ident) type += std::string(rest[k++].text);
    std::string name;
    if (k < rest.size()) name = std::string(rest[k++].text);
    while (k < rest.size()) type += std::string(rest[k++].text);  // "float a[3]" is "float[3]"
    f.paramTypes.push_back(direction + type);
    f.paramNames.push_back(name);
}

// A function header: [qualifiers] type name ( params ) -- the whole statement.
bool parseFunctionHeader(const std::vector<Token>& s, GlslFunction& f) {
    std::size_t start = skipLeadingQualifiers(s);
    std::size_t open = start;
    while (open < s.size() && s[open].text != "(" && s[open].text != "=") ++open;
    if (open >= s.size() || s[open].text != "(" || open < start + 2 || !s[open - 1].ident) return false;
    if (s.back().text != ")") return false;
    int depth = 0;
    std::size_t close = open;
    for (; close < s.size(); ++close) {
        if (s[close].text == "(") ++depth;
        if (s[close].text == ")" && --depth == 0) break;
    }
    if (close + 1 != s.size()) return false;
    f.name = std::string(s[open - 1].text);
    f.returnType = join(s, start, open - 1);
    f.line = s[open - 1].line;
    std::size_t from = open + 1;
    depth = 0;
    for (std::size_t k = open + 1; k <= close; ++k) {
        if (s[k].text == "(" || s[k].text == "[") ++depth;
        if (s[k].text == ")" || s[k].text == "]") --depth;
        if ((s[k].text == "," && depth == 0) || k == close) {
            parseParameter(s, from, k, f);
            from = k + 1;
        }
    }
    return true;
}

// Top-level variables of a declaration "[qualifiers] type a = ..., b[2];"; names after a
// struct or block body ("} instance;") when the statement had one (marked by the token "{}").
void collectDeclarators(const std::vector<Token>& s, std::vector<GlslName>& out) {
    std::size_t start = skipLeadingQualifiers(s);
    if (start < s.size() && s[start].text == "precision") return;
    auto body = std::find_if(s.begin(), s.end(), [](const Token& t) { return t.text == "{}"; });
    if (body != s.end()) {
        if (start + 1 < s.size() && s[start].text == "struct" && s[start + 1].ident)
            out.push_back({std::string(s[start + 1].text), s[start + 1].line, "struct", ""});
        start = std::size_t(body - s.begin()) + 1;
    }
    int depth = 0;
    bool initialiser = false;
    const Token* last = nullptr;
    auto flush = [&] {
        if (last && !isQualifier(last->text)) out.push_back({std::string(last->text), last->line, "variable", ""});
        last = nullptr;
    };
    for (std::size_t k = start; k < s.size(); ++k) {
        std::string_view w = s[k].text;
        if (w == "(" || w == "[") ++depth;
        if (w == ")" || w == "]") --depth;
        if (depth != 0) continue;
        if (w == "=" && !initialiser) {
            flush();
            initialiser = true;
        } else if (w == ",") {
            if (!initialiser) flush();
            initialiser = false;
        } else if (s[k].ident && !initialiser) {
            last = &s[k];
        }
    }
    if (!initialiser) flush();
}

std::string collapseSpaces(std::string_view text) {
    std::string out;
    for (char c : text) {
        bool space = c == ' ' || c == '\t' || c == '\\' || c == '\r' || c == '\n';
        if (space) {
            if (!out.empty() && out.back() != ' ') out += ' ';
        } else {
            out += c;
        }
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

}  // namespace

std::string GlslFunction::signature() const {
    std::string out = name + "(";
    for (std::size_t k = 0; k < paramTypes.size(); ++k) out += (k ? ", " : "") + paramTypes[k];
    return out + ")";
}

std::string GlslFunction::declaration() const {
    std::string out = returnType + " " + name + "(";
    for (std::size_t k = 0; k < paramTypes.size(); ++k)
        out += (k ? ", " : "") + paramTypes[k] + (paramNames[k].empty() ? "" : " " + paramNames[k]);
    return out + ")";
}

GlslScan scanGlsl(std::string_view text) {
    GlslScan scan;
    std::vector<Token> statement;   // the top-level declaration being read
    std::vector<int> braces;        // lines of the '{' still open
    std::vector<int> parens;        // lines of the '(' still open
    bool functionBody = false;      // the outermost open '{' is a function's
    bool lineStart = true;          // only white space so far on this line
    int line = 1;
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
            lineStart = true;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < n && text[i + 1] == '/') {
            while (i < n && text[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < n && text[i + 1] == '*') {
            i += 2;
            while (i < n && !(text[i] == '*' && i + 1 < n && text[i + 1] == '/')) line += text[i++] == '\n';
            i = std::min(n, i + 2);
            continue;
        }
        if (c == '#' && lineStart) {  // a directive: to the end of the line, over "\" line ends
            std::size_t start = i;
            int startLine = line;
            while (i < n && text[i] != '\n') {
                if (text[i] == '\\' && i + 1 < n && text[i + 1] == '\n') {
                    ++line;
                    ++i;
                } else if (text[i] == '/' && i + 1 < n && text[i + 1] == '/') {
                    break;  // the rest of the line is a comment; the loop above skips it
                }
                ++i;
            }
            std::string_view directive = text.substr(start + 1, i - start - 1);
            std::size_t k = directive.find_first_not_of(" \t");
            if (k != std::string_view::npos && directive.substr(k, 6) == "define") {
                k = directive.find_first_not_of(" \t", k + 6);
                std::size_t e = k;
                while (e < directive.size() && identChar(directive[e])) ++e;
                if (k != std::string_view::npos && e > k)
                    scan.names.push_back({std::string(directive.substr(k, e - k)), startLine, "macro",
                                          collapseSpaces(directive.substr(e))});
            }
            continue;
        }
        lineStart = false;
        Token token;
        token.line = line;
        std::size_t start = i;
        if (identStart(c)) {
            while (i < n && identChar(text[i])) ++i;
            token.ident = true;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
            while (i < n && (identChar(text[i]) || text[i] == '.' ||
                             ((text[i] == '+' || text[i] == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E'))))
                ++i;
        } else {
            ++i;
            if (static_cast<unsigned char>(c) >= 0x80) {  // a UTF-8 sequence: one token
                while (i < n && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
                if (!scan.nonAsciiLine) {
                    scan.nonAsciiLine = line;
                    unsigned char lead = static_cast<unsigned char>(c);
                    unsigned cp = lead >= 0xF0 ? lead & 0x07u : lead >= 0xE0 ? lead & 0x0Fu : lead & 0x1Fu;
                    for (std::size_t k = start + 1; k < i; ++k) cp = (cp << 6) | (static_cast<unsigned char>(text[k]) & 0x3Fu);
                    scan.nonAsciiCodePoint = cp;
                }
            }
        }
        token.text = text.substr(start, i - start);
        scan.lastCodeLine = line;

        if (c == '(') parens.push_back(line);
        if (c == ')' && !parens.empty()) parens.pop_back();
        if ((c == '{' || c == '}') && !parens.empty()) {  // no '(' spans a brace in GLSL: one was left open
            if (!scan.unclosedParenLine) scan.unclosedParenLine = parens.front();
            parens.clear();
        }
        if (c == '{') {
            if (braces.empty()) {
                GlslFunction f;
                functionBody = parseFunctionHeader(statement, f);
                if (functionBody) {
                    f.hasBody = true;
                    scan.functions.push_back(std::move(f));
                }
            }
            braces.push_back(line);
            continue;
        }
        if (c == '}') {
            if (braces.empty()) continue;  // a stray '}': the driver names its line
            braces.pop_back();
            if (braces.empty()) {
                if (functionBody) statement.clear();
                else statement.push_back({"{}", line, false});
                functionBody = false;
            }
            continue;
        }
        if (!braces.empty()) {  // inside a body: only the braces matter here, and NOT_STARTED
            if (functionBody && token.ident && token.text == "NOT_STARTED" && !scan.functions.empty())
                scan.functions.back().bodyNamesNotStarted = true;
            continue;
        }
        if (c == ';' && parens.empty()) {
            GlslFunction f;
            if (parseFunctionHeader(statement, f)) scan.functions.push_back(std::move(f));
            else collectDeclarators(statement, scan.names);
            statement.clear();
            continue;
        }
        statement.push_back(token);
    }
    if (!braces.empty()) scan.unclosedBraceLine = braces.front();
    if (!parens.empty() && !scan.unclosedParenLine) scan.unclosedParenLine = parens.front();
    if (!statement.empty()) scan.openStatementLine = statement.front().line;
    return scan;
}

std::vector<std::string> quotedIdentifiers(std::string_view message) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < message.size(); ++i) {
        char q = message[i];
        if (q != '`' && q != '"' && q != '\'') continue;
        std::size_t j = i + 1;
        if (j >= message.size() || !identStart(message[j])) continue;
        while (j < message.size() && identChar(message[j])) ++j;
        if (j < message.size() && (message[j] == '\'' || message[j] == '"' || message[j] == '('))
            out.emplace_back(message.substr(i + 1, j - i - 1));
        i = j - 1;
    }
    return out;
}

}  // namespace rl
