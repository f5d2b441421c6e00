#include "shader/portability.h"

#include "core/message.h"
#include "gl/gl_api.h"
#include "shader/driver_log.h"
#include "shader/program.h"

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

// `code` in backquotes, trimmed and cut for the terminal.
std::string codeSpan(const std::string& code) { return "`" + shown(code) + "`"; }

// Splits "a, f(b, c), d" at its top-level commas (positions kept); `close`
// is the closing parenthesis, npos when the line ends first.
std::vector<std::pair<std::size_t, std::size_t>> splitArguments(const std::string& line, std::size_t open,
                                                                std::size_t& close) {
    std::vector<std::pair<std::size_t, std::size_t>> args;
    int depth = 0;
    std::size_t start = open + 1;
    for (std::size_t i = open + 1; i < line.size(); ++i) {
        char c = line[i];
        if (c == '(' || c == '[') ++depth;
        else if ((c == ')' || c == ']') && depth > 0) --depth;
        else if ((c == ')' || c == ',') && depth == 0) {
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

bool isScalarInt(const std::string& t) { return t == "int" || t == "uint"; }
bool isFloatType(const std::string& t) { return t == "float" || t.rfind("vec", 0) == 0 || t.rfind("mat", 0) == 0; }

// A call `name(T1, T2, ...)` that mixes float and int arguments, found on
// the line (the first call of that name with as many arguments), rewritten
// with each int argument as a float: a literal gets its point, anything else
// float(...). "" when the line does not show the call.
std::string callFix(const std::string& name, const std::vector<std::string>& types, const std::string& line) {
    bool anyFloat = false;
    for (const auto& t : types) anyFloat = anyFloat || isFloatType(t);
    if (!anyFloat) return "";
    for (std::size_t at = line.find(name); at != std::string::npos; at = line.find(name, at + 1)) {
        if ((at > 0 && identChar(line[at - 1])) || identChar(line[at + name.size()])) continue;
        std::size_t open = line.find_first_not_of(" \t", at + name.size());
        if (open == std::string::npos || line[open] != '(') continue;
        std::size_t close = 0;
        auto args = splitArguments(line, open, close);
        if (close == std::string::npos || args.size() != types.size()) continue;
        std::string call = name + "(";
        for (std::size_t k = 0; k < args.size(); ++k) {
            std::string arg = trim(line.substr(args[k].first, args[k].second - args[k].first));
            if (isScalarInt(types[k])) {
                bool literal = !arg.empty() && arg.find_first_not_of("0123456789") == std::string::npos;
                arg = literal ? arg + ".0" : "float(" + arg + ")";
            }
            call += (k ? ", " : "") + arg;
        }
        return "write " + codeSpan(call + ")");
    }
    return "";
}

// The line with its integer literals written as floats (floatLiterals), as
// "write `...`"; "" when it has none.
std::string lineFix(const std::string& line) {
    bool changed = false;
    std::string rewritten = floatLiterals(line, changed);
    return changed ? "write " + codeSpan(rewritten) : "";
}

}  // namespace

// Mesa's columns are not used: its preprocessor collapses white space and
// expands macros before the compiler counts, so they drift from the line the
// student wrote. The fixes are found on the line itself.
std::string explainPortability(const std::string& message, const std::string& line) {
    std::string what, fix;
    auto with = [&](const std::string& otherwise) { return what + ": " + (fix.empty() ? otherwise : fix); };
    // Mesa: "no matching function for call to `pow(float, int)'; candidates are:"
    const std::string noMatch = "no matching function for call to `";
    if (auto at = message.find(noMatch); at != std::string::npos) {
        std::string call = message.substr(at + noMatch.size());
        call = call.substr(0, call.find('\''));
        auto open = call.find('(');
        if (open != std::string::npos && call.back() == ')') {
            what = call + " does not exist in GLSL ES";
            fix = callFix(call.substr(0, open), splitTypes(call.substr(open + 1, call.size() - open - 2)), line);
            return with("write the int arguments as floats: 5.0, float(n)");
        }
    }
    if (message.find("could not implicitly convert operands to arithmetic operator") != std::string::npos) {
        what = "an int in float arithmetic";
        fix = lineFix(line);
        return with("convert the int with float(...)");
    }
    if (message.find("operands of `") != std::string::npos && message.find("must have the same type") != std::string::npos) {
        std::string op = message.substr(message.find('`') + 1);
        op = op.substr(0, op.find('\''));
        what = "`" + op + "` between a float and an int";
        fix = lineFix(line);
        return with("convert the int with float(...)");
    }
    if (message.find("second and third operands of ?: operator") != std::string::npos) {
        what = "?: with a float and an int branch";
        fix = lineFix(line);
        return with("make both branches floats");
    }
    // "initializer of type int cannot be assigned to variable of type float",
    // "value of type int cannot be assigned to variable of type float".
    if (message.find("of type int cannot be assigned to variable of type float") != std::string::npos) {
        what = message.rfind("initializer", 0) == 0 ? "an int initialises a float" : "an int assigned to a float";
        fix = lineFix(line);
        std::size_t equals = line.find('=');
        if (fix.empty() && equals != std::string::npos) {
            std::size_t end = line.find(';', equals);
            std::string value = trim(line.substr(equals + 1, end == std::string::npos ? std::string::npos : end - equals - 1));
            fix = "write " + codeSpan(line.substr(0, equals + 1) + " float(" + value + ");");
        }
        return with("convert the int with float(...)");
    }
    // "`return' with wrong type int, in function `f' returning type float"
    if (message.find("`return' with wrong type int") != std::string::npos) {
        what = "a float function returns an int";
        fix = lineFix(line);
        return with("return float(...)");
    }
    return message;
}

std::string portabilityErrors(const AssembledSource& es) {
    std::string log;
    GLuint shader = compileShaderStage(GL_FRAGMENT_SHADER, es.text, log);
    if (shader) {
        gl::DeleteShader(shader);
        return "";
    }
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
               ": portability error: " + explainPortability(m.text, raw) + "\n    " + shown(raw);
        ++shownErrors;
    }
    if (more) out += "\n... and " + std::to_string(more) + " more line" + (more == 1 ? "" : "s") + " the same way";
    return out;
}

}  // namespace rl
