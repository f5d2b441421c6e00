#include "shader/portability.h"

#include "core/message.h"
#include "gl/gl_api.h"
#include "shader/driver_log.h"

#include <cctype>
#include <set>
#include <utility>
#include <vector>

namespace rl {

const char* const kPortabilityHint =
    "Mesa's desktop GLSL turns an int into a float where one is needed; GLSL ES 3.00 (browsers, macOS, "
    "stricter drivers) never does: write float constants with a point (5.0) and convert int values with float(n)";

namespace {

// Portability errors shown for one file set; the count of the rest follows.
constexpr std::size_t kMaxShownErrors = 5;
// Longest fix quoted: a real expression fits; a 10,000-character line does not flood the terminal.
constexpr std::size_t kMaxShownFix = 160;

bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string trim(const std::string& s) {
    auto first = s.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

// From `begin`, the end of the expression: a ';' or '{', or a ')' / ',' that
// closes nothing opened inside it.
std::size_t expressionEnd(const std::string& line, std::size_t begin) {
    int depth = 0;
    for (std::size_t i = begin; i < line.size(); ++i) {
        char c = line[i];
        if (c == '(' || c == '[') ++depth;
        else if ((c == ')' || c == ']') && depth-- == 0) return i;
        else if (c == ',' && depth == 0) return i;
        else if (c == ';' || c == '{') return i;
    }
    return line.size();
}

// `expression` with each integer literal that takes part in float arithmetic
// written as a float (5 -> 5.0). Literals inside an index ([i + 1]) or inside
// a constructor (int(...), float(i + 1), vec3(1, 0, 0)) stay as they are; so do 0x.. and 5u.
// `changed` says whether anything was rewritten.
std::string floatLiterals(const std::string& expression, bool& changed) {
    changed = false;
    std::string out;
    // One entry per open bracket: whether integers inside it must stay ints.
    std::vector<bool> keepInt;
    std::string lastWord;
    for (std::size_t i = 0; i < expression.size();) {
        char c = expression[i];
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::size_t j = i;
            while (j < expression.size() && identChar(expression[j])) ++j;
            lastWord = expression.substr(i, j - i);
            out += lastWord;
            i = j;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < expression.size() &&
                                                            std::isdigit(static_cast<unsigned char>(expression[i + 1])))) {
            std::size_t j = i;
            while (j < expression.size() && (identChar(expression[j]) || expression[j] == '.')) ++j;
            // An exponent's sign belongs to the number: 1e-5.
            while (j < expression.size() && (expression[j] == '-' || expression[j] == '+') &&
                   (expression[j - 1] == 'e' || expression[j - 1] == 'E') && expression.compare(i, 2, "0x") != 0) {
                ++j;
                while (j < expression.size() && identChar(expression[j])) ++j;
            }
            std::string number = expression.substr(i, j - i);
            bool isInt = number.find_first_not_of("0123456789") == std::string::npos;
            bool insideInt = !keepInt.empty() && keepInt.back();
            if (isInt && !insideInt) {
                out += number + ".0";
                changed = true;
            } else {
                out += number;
            }
            lastWord.clear();
            i = j;
            continue;
        }
        if (c == '(') {
            // Constructors convert their arguments themselves: float(i + 1), vec3(1, 0, 0) are right as they are.
            static const std::set<std::string> constructors = {
                "float", "int", "uint", "bool", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3",
                "uvec4", "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4"};
            keepInt.push_back(constructors.count(lastWord) > 0 || (!keepInt.empty() && keepInt.back()));
        } else if (c == '[') {
            keepInt.push_back(true);
        } else if ((c == ')' || c == ']') && !keepInt.empty()) {
            keepInt.pop_back();
        }
        if (c != ' ' && c != '\t') lastWord.clear();
        out += c;
        ++i;
    }
    return out;
}

std::string shown(const std::string& code) { return printable(trim(code), kMaxShownFix); }

// "write EXPR" with the expression's integer literals as floats, or, where
// it has none, EXPR wrapped in float(...) when `wrap`, else "".
std::string fixOf(const std::string& expression, bool wrap) {
    bool changed = false;
    std::string rewritten = floatLiterals(expression, changed);
    if (changed) return "write " + shown(rewritten);
    if (wrap && !trim(expression).empty()) return "write float(" + shown(expression) + ")";
    return "";
}

// Splits "a, f(b, c), d" at its top-level commas (positions kept).
std::vector<std::pair<std::size_t, std::size_t>> splitArguments(const std::string& line, std::size_t open,
                                                                std::size_t& close) {
    std::vector<std::pair<std::size_t, std::size_t>> args;
    int depth = 0;
    std::size_t start = open + 1;
    for (std::size_t i = open + 1; i < line.size(); ++i) {
        char c = line[i];
        if (c == '(' || c == '[') ++depth;
        else if ((c == ')' || c == ']') && depth > 0) --depth;
        else if ((c == ')' && depth == 0) || (c == ',' && depth == 0)) {
            args.emplace_back(start, i);
            start = i + 1;
            if (c == ')') {
                close = i;
                return args;
            }
        }
    }
    close = std::string::npos;
    return {};
}

std::vector<std::string> splitTypes(const std::string& list) {
    std::vector<std::string> types;
    std::size_t start = 0;
    while (start <= list.size()) {
        std::size_t comma = list.find(',', start);
        if (comma == std::string::npos) comma = list.size();
        types.push_back(trim(list.substr(start, comma - start)));
        start = comma + 1;
    }
    return types;
}

bool isIntType(const std::string& t) { return t == "int" || t == "uint" || t.rfind("ivec", 0) == 0 || t.rfind("uvec", 0) == 0; }
bool isFloatType(const std::string& t) { return t == "float" || t.rfind("vec", 0) == 0 || t.rfind("mat", 0) == 0; }

// A call `name(T1, T2, ...)` with float and int arguments mixed: the call
// rewritten with each int argument as a float.
std::string callFix(const std::string& name, const std::vector<std::string>& types, const std::string& line, int column) {
    // Mesa points at the start of the call; otherwise take the first call of that name on the line.
    std::size_t at = column > 0 ? std::size_t(column - 1) : std::string::npos;
    if (at == std::string::npos || line.compare(at, name.size(), name) != 0) {
        at = std::string::npos;
        for (std::size_t p = line.find(name); p != std::string::npos; p = line.find(name, p + 1))
            if ((p == 0 || !identChar(line[p - 1])) && !identChar(line[p + name.size()] )) {
                at = p;
                break;
            }
    }
    if (at == std::string::npos) return "";
    std::size_t open = line.find_first_not_of(" \t", at + name.size());
    if (open == std::string::npos || line[open] != '(') return "";
    std::size_t close = 0;
    auto args = splitArguments(line, open, close);
    if (close == std::string::npos || args.size() != types.size()) return "";
    bool anyFloat = false;
    for (const auto& t : types) anyFloat = anyFloat || isFloatType(t);
    if (!anyFloat) return "";
    std::string call = name + "(";
    for (std::size_t k = 0; k < args.size(); ++k) {
        std::string arg = trim(line.substr(args[k].first, args[k].second - args[k].first));
        if (isIntType(types[k]) && types[k].find("vec") == std::string::npos) {
            bool changed = false;
            std::string asFloat = floatLiterals(arg, changed);
            bool literal = arg.find_first_not_of("0123456789") == std::string::npos;
            arg = literal ? asFloat : "float(" + arg + ")";
        }
        call += (k ? ", " : "") + arg;
    }
    return "write " + shown(call + ")");
}

std::string afterWord(const std::string& line, std::size_t from, const std::string& word) {
    std::size_t at = line.find(word, from);
    return at == std::string::npos ? "" : line.substr(at + word.size(), expressionEnd(line, at + word.size()) -
                                                                           (at + word.size()));
}

}  // namespace

std::string explainPortability(const std::string& message, const std::string& line, int column) {
    const std::size_t start = column > 0 && std::size_t(column - 1) < line.size() ? std::size_t(column - 1) : 0;
    const std::string expression = line.substr(start, expressionEnd(line, start) - start);
    std::string what, fix;
    auto with = [&](const std::string& text) { return what + (text.empty() ? "" : ": " + text); };
    // Mesa: "no matching function for call to `pow(float, int)'; candidates are:"
    const std::string noMatch = "no matching function for call to `";
    if (auto at = message.find(noMatch); at != std::string::npos) {
        std::string call = message.substr(at + noMatch.size());
        call = call.substr(0, call.find('\''));
        auto open = call.find('(');
        if (open != std::string::npos && call.back() == ')') {
            std::string name = call.substr(0, open);
            auto types = splitTypes(call.substr(open + 1, call.size() - open - 2));
            what = call + " does not exist in GLSL ES";
            fix = callFix(name, types, line, column);
            if (fix.empty()) fix = "convert the int arguments with float(...) or write them as 5.0";
            return with(fix);
        }
    }
    if (message.find("could not implicitly convert operands to arithmetic operator") != std::string::npos) {
        what = "an int in float arithmetic";
        fix = fixOf(expression, false);
        return with(fix.empty() ? "convert the int with float(...)" : fix);
    }
    if (message.find("operands of `") != std::string::npos && message.find("must have the same type") != std::string::npos) {
        std::string op = message.substr(message.find('`') + 1);
        op = op.substr(0, op.find('\''));
        what = "`" + op + "` between a float and an int";
        fix = fixOf(expression, false);
        return with(fix.empty() ? "convert the int with float(...)" : fix);
    }
    if (message.find("second and third operands of ?: operator") != std::string::npos) {
        what = "?: with a float and an int branch";
        // Mesa points at the second operand: the fix covers both branches.
        fix = fixOf(expression, false);
        std::size_t question = line.rfind('?', start);
        if (question != std::string::npos) {
            std::size_t from = line.find_first_not_of(" \t", question + 1);
            std::size_t colon = line.find(':', from);
            if (colon != std::string::npos) {
                std::size_t end = expressionEnd(line, colon + 1);
                bool changed = false;
                std::string branches = floatLiterals(line.substr(from, end - from), changed);
                if (changed) fix = "write ? " + shown(branches);
            }
        }
        return with(fix.empty() ? "make both branches floats" : fix);
    }
    // "initializer of type int cannot be assigned to variable of type float",
    // "value of type int cannot be assigned to variable of type float".
    if (message.find("of type int cannot be assigned to variable of type float") != std::string::npos) {
        what = message.rfind("initializer", 0) == 0 ? "an int initialises a float" : "an int assigned to a float";
        std::string value = afterWord(line, start, "=");
        fix = fixOf(value, true);
        return with(fix);
    }
    // "`return' with wrong type int, in function `f' returning type float"
    if (message.find("`return' with wrong type int") != std::string::npos) {
        what = "a float function returns an int";
        fix = fixOf(afterWord(line, 0, "return"), true);
        return with(fix);
    }
    return message;
}

std::string portabilityErrors(const AssembledSource& es) {
    GLuint shader = gl::CreateShader(GL_FRAGMENT_SHADER);
    const char* text = es.text.c_str();
    gl::ShaderSource(shader, 1, &text, nullptr);
    gl::CompileShader(shader);
    GLint ok = 0, length = 0;
    gl::GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    gl::GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 0)), '\0');
    if (length > 0) gl::GetShaderInfoLog(shader, length, nullptr, log.data());
    gl::DeleteShader(shader);
    if (ok) return "";
    std::string out;
    std::size_t shownErrors = 0, more = 0;
    std::set<std::pair<std::string, int>> seen;  // one error per line: the first is the cause, the rest follow
    for (const DriverMessage& m : parseDriverLog(log)) {
        if (m.severity != "error") continue;
        if (!m.text.empty() && (m.text[0] == ' ' || m.text[0] == '\t')) continue;  // Mesa's list of candidates
        auto where = es.locate(m.line);
        if (!where) continue;
        const SourceFile* file = es.source(where->file);
        if (!file || !file->exercise) continue;
        if (!seen.insert({where->file, where->line}).second) continue;
        if (shownErrors == kMaxShownErrors) {
            ++more;
            continue;
        }
        const std::string raw = es.lineText(m.line);
        out += (out.empty() ? "" : "\n") + where->file + ":" + std::to_string(where->line) +
               ": portability error: " + explainPortability(m.text, raw, m.column) + "\n    " + shown(raw);
        ++shownErrors;
    }
    if (more) out += "\n... and " + std::to_string(more) + " more line" + (more == 1 ? "" : "s") + " the same way";
    return out;
}

}  // namespace rl
