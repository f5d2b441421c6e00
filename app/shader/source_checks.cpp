#include "shader/source_checks.h"

#include "shader/glsl_scan.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <string>

namespace fs = std::filesystem;

namespace rl {

namespace {

// The text of a 1-based line of a file, without leading white space.
std::string lineOf(const std::string& text, int line) {
    std::size_t pos = 0;
    for (int k = 1; k < line && pos != std::string::npos; ++k) {
        pos = text.find('\n', pos);
        if (pos != std::string::npos) ++pos;
    }
    if (pos == std::string::npos || pos >= text.size()) return {};
    std::size_t end = text.find('\n', pos);
    std::string out = text.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    if (!out.empty() && out.back() == '\r') out.pop_back();
    std::size_t first = out.find_first_not_of(" \t");
    return first == std::string::npos ? std::string() : out.substr(first);
}

// Source lines are looked up for the first errors only: the rest are counted, not printed.
constexpr std::size_t kErrorsWithSourceLine = 32;

ShaderDiagnostic at(const SourceFile& file, int line, std::string message, bool withLine = true) {
    ShaderDiagnostic d;
    d.where = {file.shown, line};
    d.severity = "error";
    d.message = std::move(message);
    if (line > 0 && withLine) d.sourceLine = lineOf(file.text, line);
    return d;
}

std::string location(const SourceFile& file, int line) { return file.shown + ":" + std::to_string(line); }

// The prototypes of the generated exercise_declarations.glsl (the units'
// signatures, shader/readiness.cpp) by exercise file ("05-ggx.glsl"): a
// comment line "// 05-ggx" starts each exercise's list.
std::map<std::string, std::vector<GlslFunction>> contractOf(const SourceFile& declarations) {
    std::vector<std::string> sectionOfLine{""};  // index 0 unused
    std::string section;
    std::size_t pos = 0;
    const std::string& text = declarations.text;
    while (pos <= text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + pos, end - pos);
        if (line.size() > 6 && line.substr(0, 3) == "// " && std::isdigit(static_cast<unsigned char>(line[3])) &&
            std::isdigit(static_cast<unsigned char>(line[4])) && line[5] == '-') {
            std::size_t stop = line.find_first_of(" \t\r", 3);
            section = std::string(line.substr(3, stop == std::string_view::npos ? std::string_view::npos : stop - 3));
        } else if (line.substr(0, 12) == "// Framework") {
            section.clear();
        }
        sectionOfLine.push_back(section);
        pos = end + 1;
    }
    std::map<std::string, std::vector<GlslFunction>> contract;
    for (const GlslFunction& f : scanGlsl(text).functions) {
        if (f.line <= 0 || std::size_t(f.line) >= sectionOfLine.size()) continue;
        const std::string& s = sectionOfLine[std::size_t(f.line)];
        if (!s.empty() && !f.hasBody) contract[s + ".glsl"].push_back(f);
    }
    return contract;
}

bool structurallyOpen(const GlslScan& s) {
    return s.unclosedBraceLine || s.unclosedParenLine || s.openStatementLine;
}

const char* kTogether = "the exercise files are compiled together, so rename one of them";

}  // namespace

std::vector<ShaderDiagnostic> checkExerciseSources(const AssembledSource& source) {
    std::vector<ShaderDiagnostic> errors;
    // Errors past the first few are counted without their source line.
    auto at = [&errors](const SourceFile& file, int line, std::string message) {
        return rl::at(file, line, std::move(message), errors.size() < kErrorsWithSourceLine);
    };
    const std::size_t count = source.sources.size();
    std::vector<GlslScan> scans(count);
    std::vector<bool> skip(count, false);  // the owner's scope is left open: the compile will say where
    const SourceFile* declarations = nullptr;
    for (std::size_t i = 0; i < count; ++i) {
        const SourceFile& f = source.sources[i];
        if (!f.exercise) {
            if (f.path.filename() == "exercise_declarations.glsl") declarations = &f;
            continue;
        }
        scans[i] = scanGlsl(f.text);
        if (structurallyOpen(scans[i])) skip[std::size_t(f.owner)] = true;
    }
    auto skipped = [&](std::size_t i) { return !source.sources[i].exercise || skip[std::size_t(source.sources[i].owner)]; };

    // Outside comments GLSL is ASCII; drivers differ on the rest (Mesa
    // silently dropped the code after a U+FEFF in the middle of a file).
    for (std::size_t i = 0; i < count; ++i) {
        if (!source.sources[i].exercise || !scans[i].nonAsciiLine) continue;
        char code[16];
        std::snprintf(code, sizeof code, "U+%04X", scans[i].nonAsciiCodePoint);
        errors.push_back(at(source.sources[i], scans[i].nonAsciiLine,
                            std::string("character ") + code +
                                " outside a comment: GLSL code is ASCII (was it pasted from a document?)"));
    }

    // main() belongs to the framework.
    for (std::size_t i = 0; i < count; ++i) {
        if (skipped(i)) continue;
        for (const GlslFunction& f : scans[i].functions)
            if (f.name == "main" && f.hasBody)
                errors.push_back(at(source.sources[i], f.line,
                                    "exercise files must not define main(): raylab's shaders/main.frag has it; "
                                    "remove or rename this one"));
    }

    // The contract: every function of the exercise, with its parameters and return type.
    if (declarations) {
        const auto contract = contractOf(*declarations);
        for (std::size_t i = 0; i < count; ++i) {
            const SourceFile& file = source.sources[i];
            if (skipped(i) || file.owner != int(i)) continue;
            auto it = contract.find(fs::path(file.includedAs).filename().string());
            if (it == contract.end()) continue;
            for (const GlslFunction& want : it->second) {
                const GlslFunction* exact = nullptr;
                const GlslFunction* sameName = nullptr;
                const GlslFunction* prototype = nullptr;
                const SourceFile* in = &file;
                for (std::size_t j = 0; j < count && !exact; ++j) {
                    if (skipped(j) || source.sources[j].owner != int(i)) continue;
                    for (const GlslFunction& f : scans[j].functions) {
                        if (f.name != want.name) continue;
                        bool same = f.paramTypes == want.paramTypes;
                        if (same && f.hasBody) {
                            exact = &f;
                            in = &source.sources[j];
                            break;
                        }
                        if (same && !prototype) prototype = &f;
                        if (!same && f.hasBody && !sameName) {
                            sameName = &f;
                            in = &source.sources[j];
                        }
                    }
                }
                const std::string expected = "expected " + want.declaration() + ")";
                if (exact) {
                    if (exact->returnType != want.returnType)
                        errors.push_back(at(*in, exact->line,
                                            want.name + " returns " + exact->returnType + " (" + expected));
                } else if (sameName) {
                    errors.push_back(at(*in, sameName->line,
                                        want.name + " has the wrong parameters: " + sameName->signature() + " (" +
                                            expected));
                } else if (prototype) {
                    errors.push_back(at(file, prototype->line,
                                        want.name + " is declared but has no body (" + expected));
                } else {
                    errors.push_back(at(file, 0, want.name + " is missing (" + expected));
                }
            }
        }
    }

    // The same name defined in two exercise files.
    struct First {
        std::size_t file;
        int line;
        std::string body;  // a macro's text
    };
    std::map<std::string, First> functions, functionNames, names, macros;
    for (std::size_t i = 0; i < count; ++i) {
        if (skipped(i)) continue;
        const SourceFile& file = source.sources[i];
        auto other = [&](const First& f) { return source.sources[f.file].owner != file.owner; };
        for (const GlslFunction& f : scans[i].functions) {
            if (!f.hasBody) continue;
            functionNames.emplace(f.name, First{i, f.line, ""});
            auto [it, fresh] = functions.emplace(f.signature(), First{i, f.line, ""});
            if (!fresh && other(it->second))
                errors.push_back(at(file, f.line,
                                    f.signature() + " is also defined in " +
                                        location(source.sources[it->second.file], it->second.line) + ": " + kTogether));
            auto var = names.find(f.name);
            if (var != names.end() && other(var->second))
                errors.push_back(at(file, f.line,
                                    f.name + " is also declared in " +
                                        location(source.sources[var->second.file], var->second.line) + ": " +
                                        kTogether));
        }
        for (const GlslName& n : scans[i].names) {
            if (n.kind == "macro") {
                auto [it, fresh] = macros.emplace(n.name, First{i, n.line, n.body});
                if (!fresh && other(it->second) && it->second.body != n.body)
                    errors.push_back(at(file, n.line,
                                        "macro " + n.name + " is also defined, differently, in " +
                                            location(source.sources[it->second.file], it->second.line) + ": " +
                                            kTogether));
                continue;
            }
            auto [it, fresh] = names.emplace(n.name, First{i, n.line, ""});
            if (!fresh && other(it->second))
                errors.push_back(at(file, n.line,
                                    n.name + " is also declared in " +
                                        location(source.sources[it->second.file], it->second.line) + ": " + kTogether));
            auto fn = functionNames.find(n.name);
            if (fn != functionNames.end() && other(fn->second))
                errors.push_back(at(file, n.line,
                                    n.name + " is also a function in " +
                                        location(source.sources[fn->second.file], fn->second.line) + ": " +
                                        kTogether));
        }
    }
    return errors;
}

void explainDriverDiagnostics(std::vector<ShaderDiagnostic>& diagnostics, const AssembledSource& source) {
    bool anyExercise = std::any_of(source.sources.begin(), source.sources.end(),
                                   [](const SourceFile& f) { return f.exercise; });
    if (!anyExercise) return;
    std::map<std::string, GlslScan> scans;  // by shown name, scanned when first needed
    auto scanOf = [&](const SourceFile& f) -> const GlslScan& {
        auto it = scans.find(f.shown);
        if (it == scans.end()) it = scans.emplace(f.shown, scanGlsl(f.text)).first;
        return it->second;
    };
    // Top-level names of the exercise files -> where they are declared first.
    std::map<std::string, std::pair<const SourceFile*, int>> declared;
    bool declaredFilled = false;
    auto declaredAt = [&](const std::string& name) -> const std::pair<const SourceFile*, int>* {
        if (!declaredFilled) {
            declaredFilled = true;
            for (const SourceFile& f : source.sources) {
                if (!f.exercise) continue;
                const GlslScan& s = scanOf(f);
                for (const GlslFunction& fn : s.functions)
                    if (fn.hasBody) declared.emplace(fn.name, std::make_pair(&f, fn.line));
                for (const GlslName& n : s.names) declared.emplace(n.name, std::make_pair(&f, n.line));
            }
        }
        auto it = declared.find(name);
        return it == declared.end() ? nullptr : &it->second;
    };
    // Only the first diagnostics are printed (program.cpp): explain those.
    constexpr std::size_t kExplained = 64;
    for (std::size_t k = 0; k < diagnostics.size() && k < kExplained; ++k) {
        ShaderDiagnostic& d = diagnostics[k];
        if (d.severity != "error") continue;
        if (d.where.file.empty()) {
            // A link error has no line: a function an exercise file declares
            // and no file defines is the usual one.
            bool moved = false;
            for (const std::string& name : quotedIdentifiers(d.message)) {
                for (const SourceFile& f : source.sources) {
                    if (!f.exercise || moved) continue;
                    for (const GlslFunction& fn : scanOf(f).functions) {
                        if (fn.name != name || fn.hasBody) continue;
                        d = at(f, fn.line,
                               name + " is declared here but no file defines it (the driver says: " + d.message + ")");
                        moved = true;
                        break;
                    }
                }
                if (moved) break;
            }
            if (!moved) d.message += " [the driver names no line: a problem between the files]";
            continue;
        }
        const SourceFile* file = source.source(d.where.file);
        if (!file) continue;
        if (d.where.endOfFile) {
            // The driver stopped at the line that closes the file's scope.
            const GlslScan& s = scanOf(*file);
            if (s.unclosedBraceLine) {
                d = at(*file, s.unclosedBraceLine, "this '{' is not closed by the end of the file (a '}' is missing)");
            } else if (s.unclosedParenLine) {
                d = at(*file, s.unclosedParenLine, "this '(' is not closed by the end of the file (a ')' is missing)");
            } else if (s.openStatementLine) {
                int line = std::max(s.lastCodeLine, s.openStatementLine);
                d = at(*file, line, "the file ends inside a declaration: is a ';' missing at the end of this line?");
            } else {
                d = at(*file, std::max(1, s.lastCodeLine), "at the end of the file: " + d.message);
            }
            continue;
        }
        if (file->exercise) continue;
        // An error in a framework file: the framework compiles with the
        // solutions, so an exercise file caused it. Which one, when the
        // driver quotes a name an exercise file declares too.
        bool moved = false;
        for (const std::string& name : quotedIdentifiers(d.message)) {
            const auto* found = declaredAt(name);
            if (!found) continue;
            std::string framework = d.where.file + ":" + std::to_string(d.where.line);
            d = at(*found->first, found->second,
                   name + " is also declared by raylab in " + framework + ": rename yours (the driver says: " +
                       d.message + ")");
            moved = true;
            break;
        }
        // An #error of the framework's own (a student edition's
        // model_variants.glsl) says what it means: no exercise caused it.
        if (!moved && d.message.find("#error") == std::string::npos)
            d.message += " [in raylab's own file, which compiles with the solutions: the cause is in an exercise "
                         "file included before this line]";
    }
}

}  // namespace rl
