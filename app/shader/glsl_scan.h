// A small, linear scan of GLSL source for what the host checks before the
// driver sees an exercise file: the top-level functions, variables and
// macros it declares (with their lines), and whether its braces, parentheses
// and last declaration are closed by the end of the file. It is not a
// parser: it tokenises once, keeps brace depth in counters and a list, and
// never recurses, so any input (a 30,000-space line, 10,000 nested braces)
// costs time linear in its length.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rl {

struct GlslFunction {
    std::string name;
    std::string returnType;              // "float", "vec3"
    std::vector<std::string> paramTypes; // "vec3", "out vec3", "float[3]"; empty for (void)
    std::vector<std::string> paramNames; // "" where the declaration names none
    int line = 0;                        // 1-based line of the name
    bool hasBody = false;                // a definition, not a prototype
    // Its body names NOT_STARTED outside comments: the function is still a
    // stub, or a stub partly filled in (shader/readiness.h).
    bool bodyNamesNotStarted = false;

    std::string signature() const;  // "pow5(float)": what makes two definitions clash
    std::string declaration() const;  // "float D_GGX(vec3 n, vec3 h, float alpha)"
};

struct GlslName {
    std::string name;
    int line = 0;
    std::string kind;  // "variable", "struct", "macro"
    std::string body;  // a macro's replacement text, white space collapsed
};

struct GlslScan {
    std::vector<GlslFunction> functions;  // top-level definitions and prototypes, in order
    std::vector<GlslName> names;          // top-level variables (const, uniform, globals), structs, macros
    int unclosedBraceLine = 0;  // line of the outermost '{' still open at the end; 0 when none
    int unclosedParenLine = 0;  // line of the outermost '(' still open at the end; 0 when none
    int openStatementLine = 0;  // line where an unterminated top-level declaration starts; 0 when none
    int lastCodeLine = 0;       // last line with a token
    // The first character outside the ASCII set outside comments (GLSL source
    // is ASCII there; a minus sign or quote pasted from a PDF is not):
    int nonAsciiLine = 0;       // its line; 0 when none
    unsigned nonAsciiCodePoint = 0;
};

GlslScan scanGlsl(std::string_view text);

// The names quoted in a driver message (`name', "name", 'name'), in order.
std::vector<std::string> quotedIdentifiers(std::string_view message);

}  // namespace rl
