#include "grading/class_fixture.h"

#include "course/exercise_registry.h"
#include "core/paths.h"
#include "support/test_support.h"

#include <zip.h>

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

}  // namespace rl::test
