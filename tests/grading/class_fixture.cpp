#include "grading/class_fixture.h"

#include "course/exercise_registry.h"
#include "core/paths.h"
#include "support/test_support.h"

#include <zip.h>

#include <regex>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>

namespace fs = std::filesystem;

namespace rl::test {

void writeZip(const fs::path& path, const std::vector<ZipEntry>& entries) {
    int error = 0;
    zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    if (!z) throw std::runtime_error("cannot create " + path.string());
    for (const ZipEntry& e : entries) {
        // zip_source_buffer keeps the pointer until zip_close: the entries outlive it.
        zip_source_t* source = zip_source_buffer(z, e.content.data(), e.content.size(), 0);
        zip_int64_t index = zip_file_add(z, e.name.c_str(), source, ZIP_FL_OVERWRITE | ZIP_FL_ENC_UTF_8);
        if (index < 0) {
            zip_source_free(source);
            zip_discard(z);
            throw std::runtime_error("cannot add " + e.name + " to " + path.string());
        }
        zip_uint32_t mode = (e.symlink ? S_IFLNK | 0777 : S_IFREG | 0644);
        zip_file_set_external_attributes(z, zip_uint64_t(index), 0, ZIP_OPSYS_UNIX, mode << 16);
    }
    if (zip_close(z) != 0) throw std::runtime_error("cannot write " + path.string());
}

std::map<std::string, std::string> solutionFiles(const std::map<std::string, std::string>& replace) {
    std::map<std::string, std::string> files;
    for (const ExerciseInfo& e : allExercises()) files[e.file()] = readText(solutionsDir() / e.file());
    for (const auto& [name, text] : replace) files[name] = text;
    return files;
}

std::map<std::string, std::string> stubFiles() {
    std::map<std::string, std::string> files;
    for (const ExerciseInfo& e : allExercises()) files[e.file()] = readText(exercisesDir() / e.file());
    return files;
}

void writeFolder(const fs::path& dir, const std::map<std::string, std::string>& files) {
    fs::create_directories(dir);
    for (const auto& [name, text] : files) {
        fs::create_directories((dir / name).parent_path());
        writeText(dir / name, text);
    }
}

std::string mutantText(const std::string& name) {
    return readText(test::unitFilePath("mutants", name));
}

std::string mutantCaughtBy(const std::string& name) {
    std::string text = mutantText(name);
    const std::string marker = "contains \"";
    auto line = text.find("// caught by:");
    auto start = text.find(marker, line);
    if (line == std::string::npos || start == std::string::npos) return "";
    start += marker.size();
    return text.substr(start, text.find("\"\n", start) - start);
}

namespace {

std::string insertAfter(std::string text, const std::string& anchor, const std::string& insert) {
    auto at = text.find(anchor);
    if (at == std::string::npos) throw std::runtime_error("fixture: '" + anchor + "' not found");
    return text.insert(at + anchor.size(), insert);
}

}  // namespace

std::string endlessDisplay() {
    return insertAfter(readText(solutionsDir() / "10-display.glsl"), "vec3 toneMap(vec3 c, int op) {\n",
                       "    #define TIMES4(s) s s s s\n"
                       "    for (int i = 0; i >= 0; i += 1) { TIMES4(TIMES4(TIMES4(TIMES4(c = sin(c) + 1.0;)))) }\n");
}

std::string nanLambert() {
    std::string text = readText(solutionsDir() / "03-lambert.glsl");
    const std::string body = "    return albedo / PI;";
    auto at = text.find(body);
    if (at == std::string::npos) throw std::runtime_error("fixture: Fd_Lambert's body not found");
    return text.replace(at, body.size(),
                        "    float zero = max(albedo.r, 0.0) * 0.0;  // 0/0 at run time, not foldable\n"
                        "    return albedo / PI * (zero / zero);");
}

std::string compileErrorGgx() {
    std::string text = readText(solutionsDir() / "05-ggx.glsl");
    auto second = text.find('\n', text.find('\n') + 1);
    return text.insert(second + 1, "float broken() { return 1.0 + ; }\n");
}

namespace {

// The top-level functions of a GLSL file (a function runs from its header line to the
// line of its closing brace at column 0), and what lies before the first.
std::vector<std::string> functionsOf(const std::string& text, std::string& before) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line, current;
    bool inside = false;
    for (; std::getline(in, line);) {
        if (!inside && !line.empty() && line.find('(') != std::string::npos && line.back() == '{') inside = true;
        if (inside) {
            current += line + "\n";
            if (line == "}") {
                out.push_back(current);
                current.clear();
                inside = false;
            }
        } else if (out.empty()) {
            before += line + "\n";
        }
    }
    return out;
}

}  // namespace

std::string ownCookTorrance(int author) {
    const std::string solution = readText(solutionsDir() / "08-cook-torrance.glsl");
    const std::string a = "k" + std::to_string(author);
    // Three helpers and a specular lobe of the student's own; statements differ with the author.
    const std::string helpers =
        "float " + a + "Dot01(vec3 first, vec3 second) {\n"
        "    float d = dot(first, second);\n" +
        (author % 3 == 0   ? "    if (d < 0.0) return 0.0;\n    if (d > 1.0) return 1.0;\n    return d;\n"
         : author % 3 == 1 ? "    d = d < 0.0 ? 0.0 : d;\n    d = d > 1.0 ? 1.0 : d;\n    return d;\n"
                           : "    return min(max(d, 0.0), 1.0);\n") +
        "}\n\n"
        "vec3 " + a + "Halfway(vec3 toLight, vec3 toEye) {\n"
        "    vec3 sum = toLight + toEye;\n" +
        (author % 3 == 0 ? "    return normalize(sum);\n" : author % 3 == 1 ? "    float len = length(sum);\n    return sum / len;\n"
                                                              : "    return sum * inversesqrt(dot(sum, sum));\n") +
        "}\n\n"
        "float " + a + "Denominator(float lightCos, float viewCos) {\n" +
        (author % 3 == 0   ? "    float both = lightCos * viewCos;\n    return both * 4.0;\n"
         : author % 3 == 1 ? "    return 4.0 * lightCos * viewCos;\n"
                           : "    float four = 4.0;\n    four *= viewCos;\n    return four * lightCos;\n") +
        "}\n\n";
    std::string body;
    if (author % 3 == 0)
        body = "    float lightCos = " + a + "Dot01(n, l);\n"
               "    if (lightCos <= 0.0) return vec3(0.0);\n"
               "    float viewCos = max(" + a + "Dot01(n, v), 1e-4);\n"
               "    vec3 hv = " + a + "Halfway(l, v);\n"
               "    float dist = D_GGX(n, hv, ggxAlpha(m.roughness));\n"
               "    float geo = G_SchlickGGX(viewCos, lightCos, m.roughness);\n"
               "    vec3 fres = F_Schlick(baseReflectance(m), dot(hv, v));\n"
               "    return dist * geo * fres / " + a + "Denominator(lightCos, viewCos);\n";
    else if (author % 3 == 1)
        body = "    vec3 hv = " + a + "Halfway(l, v);\n"
               "    float viewCos = clamp(dot(n, v), 1e-4, 1.0);\n"
               "    float lightCos = max(dot(n, l), 0.0);\n"
               "    if (lightCos == 0.0) {\n        return vec3(0.0);\n    }\n"
               "    vec3 fres = F_Schlick(baseReflectance(m), max(dot(v, hv), 0.0));\n"
               "    float geo = G_SchlickGGX(viewCos, lightCos, m.roughness);\n"
               "    float dist = D_GGX(n, hv, ggxAlpha(m.roughness));\n"
               "    vec3 top = fres * (dist * geo);\n"
               "    return top / " + a + "Denominator(lightCos, viewCos);\n";
    else
        body = "    float lightCos = " + a + "Dot01(n, l);\n"
               "    float viewCos = max(" + a + "Dot01(n, v), 1e-4);\n"
               "    vec3 result = vec3(0.0);\n"
               "    if (lightCos > 0.0) {\n"
               "        vec3 hv = " + a + "Halfway(l, v);\n"
               "        float alpha = ggxAlpha(m.roughness);\n"
               "        result = D_GGX(n, hv, alpha) * G_SchlickGGX(viewCos, lightCos, m.roughness) *\n"
               "                 F_Schlick(baseReflectance(m), dot(hv, v)) / " + a + "Denominator(lightCos, viewCos);\n"
               "    }\n"
               "    return result;\n";
    const std::string specular = "vec3 specularBRDF(vec3 n, vec3 v, vec3 l, Material m) {\n" + body + "}\n";
    const std::size_t from = solution.find("// Specular lobe:");
    const std::size_t to = solution.find("// Diffuse lobe:");
    if (from == std::string::npos || to == std::string::npos) throw std::runtime_error("fixture: 08's lobes not found");
    return solution.substr(0, from) + helpers + specular + "\n" + solution.substr(to);
}

std::string renamedCopy(const std::string& text, const std::string& prefix) {
    // The student's own names: its helpers and locals (GLSL's and the course's names stay).
    static const char* const kOwn[] = {"Dot01", "Halfway", "Denominator", "first", "second", "toLight", "toEye",
                                       "sum", "len", "both", "lightCos", "viewCos", "hv", "dist", "geo", "fres", "top", "result", "alpha", "four"};
    std::string out = text;
    int k = 0;
    for (const char* name : kOwn) {
        const std::regex word(std::string("\\b(k[0-9]+)?") + name + "\\b");
        out = std::regex_replace(out, word, prefix + std::to_string(k++));
    }
    return out;
}

std::string reorderedCopy(const std::string& text) {
    std::string before;
    std::vector<std::string> functions = functionsOf(text, before);
    // GLSL needs a function declared before its use: prototypes first, then the bodies in reverse.
    std::string prototypes, bodies;
    for (auto it = functions.rbegin(); it != functions.rend(); ++it) {
        prototypes += it->substr(0, it->find(" {\n")) + ";\n";
        bodies += *it + "\n";
    }
    return before + prototypes + "\n" + bodies;
}

}  // namespace rl::test
