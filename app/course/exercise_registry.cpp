#include "course/exercise_registry.h"

#include "core/error.h"
#include "core/message.h"
#include "course/unit_sources.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

namespace rl {

namespace {

using nlohmann::json;

std::string textOf(const json& j, const std::string& where) {
    if (j.is_string()) return j.get<std::string>();
    if (j.is_array()) {  // lines
        std::string out;
        for (const json& line : j) {
            if (!line.is_string()) throw Error(where + ": every line must be a string");
            out += line.get<std::string>() + "\n";
        }
        return out;
    }
    throw Error(where + ": must be a string or an array of lines");
}

// One unit's unit.json (course/README.md describes every field). The build
// compiled it in; a unit with a mistake stops the program at its first use
// with the file and the field.
ExerciseInfo parseUnit(const UnitSource& source) {
    const std::string where = "course/" + std::string(source.id) + "/unit.json";
    json j;
    try {
        j = json::parse(source.json);
    } catch (const json::exception& e) {
        throw Error(where + ": not valid JSON (" + e.what() + ")");
    }
    ExerciseInfo e;
    e.id = source.id;
    e.number = std::stoi(e.id.substr(0, 2));
    e.inCourse = source.position >= 0;
    e.optional = source.optional;
    if (!j.is_object() || !j.contains("title") || !j["title"].is_string())
        throw Error(where + ": needs \"title\" (a string)");
    e.title = j["title"].get<std::string>();
    if (j.contains("weight")) {
        if (!j["weight"].is_number() || j["weight"].get<double>() < 0) throw Error(where + ": \"weight\" must be a number >= 0");
        e.weight = j["weight"].get<int>();
    }
    if (j.contains("shows_with")) {
        e.showsWith = textOf(j["shows_with"], where + ": \"shows_with\"");
        if (e.showsWith.rfind("RL_", 0) != 0) throw Error(where + ": \"shows_with\" must name an RL_ define");
    }
    if (j.contains("light")) e.light = textOf(j["light"], where + ": \"light\"");
    if (j.contains("bench_strategies"))
        for (const json& s : j["bench_strategies"]) {
            if (!s.is_object() || !s.contains("name") || !s.contains("mutant"))
                throw Error(where + ": every bench strategy needs \"name\" and \"mutant\"");
            e.benchStrategies.push_back({textOf(s["name"], where + ": bench strategy name"),
                                         textOf(s["mutant"], where + ": bench strategy mutant")});
        }
    if (!j.contains("functions") || !j["functions"].is_array() || j["functions"].empty())
        throw Error(where + ": needs \"functions\" (an array of at least one)");
    for (const json& f : j["functions"]) {
        ExerciseFunction fn;
        for (const char* key : {"name", "signature", "neutral", "probe"})
            if (!f.is_object() || !f.contains(key))
                throw Error(where + ": every function needs \"" + std::string(key) + "\"");
        fn.name = textOf(f["name"], where + ": \"name\"");
        fn.signature = textOf(f["signature"], where + ": \"" + fn.name + "\" signature");
        fn.neutralBody = textOf(f["neutral"], where + ": \"" + fn.name + "\" neutral");
        fn.probeCall = textOf(f["probe"], where + ": \"" + fn.name + "\" probe");
        if (f.contains("needs"))
            for (const json& n : f["needs"]) fn.needs.push_back(textOf(n, where + ": \"" + fn.name + "\" needs"));
        if (f.contains("framework_calls"))
            for (const json& n : f["framework_calls"])
                fn.frameworkCalls.push_back(textOf(n, where + ": \"" + fn.name + "\" framework_calls"));
        fn.geometry = f.value("geometry", false);
        e.functions.push_back(std::move(fn));
    }
    return e;
}

struct Course {
    std::vector<ExerciseInfo> exercises;  // the manifest's, in order
    std::vector<ExerciseInfo> framework;  // the others
};

const Course& course() {
    static const Course c = [] {
        Course out;
        for (const UnitSource& u : unitSources()) (u.position >= 0 ? out.exercises : out.framework).push_back(parseUnit(u));
        return out;
    }();
    return c;
}

}  // namespace

const std::vector<ExerciseInfo>& allExercises() { return course().exercises; }
const std::vector<ExerciseInfo>& frameworkUnits() { return course().framework; }

std::vector<ExerciseInfo> requiredExercises() {
    std::vector<ExerciseInfo> out;
    for (const ExerciseInfo& e : allExercises())
        if (!e.optional) out.push_back(e);
    return out;
}

const std::string* shippedStub(const std::string& fileName) {
    static const std::map<std::string, std::string> stubs = [] {
        std::map<std::string, std::string> out;
        for (const UnitSource& u : unitSources()) out[std::string(u.id) + ".glsl"] = u.stub;
        return out;
    }();
    auto it = stubs.find(fileName);
    return it == stubs.end() ? nullptr : &it->second;
}

const ExerciseInfo* exerciseOfFunction(const std::string& function) {
    for (const auto* units : {&allExercises(), &frameworkUnits()})
        for (const ExerciseInfo& e : *units)
            for (const ExerciseFunction& f : e.functions)
                if (f.name == function) return &e;
    return nullptr;
}

int probeFunctionId(const std::string& function) {
    int id = 0;
    for (const auto* units : {&allExercises(), &frameworkUnits()})
        for (const ExerciseInfo& e : *units)
            for (const ExerciseFunction& f : e.functions) {
                if (f.name == function) return id;
                ++id;
            }
    return -1;
}

const ExerciseInfo& findExercise(const std::string& key) {
    for (const ExerciseInfo& e : allExercises()) {
        if (key == e.id || key == e.file() || key == std::to_string(e.number) ||
            (key.size() == 2 && key[0] == '0' && key.substr(1) == std::to_string(e.number)))
            return e;
    }
    std::string valid;
    for (const ExerciseInfo& e : allExercises()) valid += (valid.empty() ? "" : ", ") + std::to_string(e.number);
    throw Error("--exercise: no exercise " + quotedValue(key) + " (expected one of " + valid + ", or a name like " +
                (allExercises().empty() ? std::string("NN-name") : allExercises().front().id) + ")");
}

std::string normalisedGlsl(const std::string& text) {
    // A UTF-8 byte-order mark (some Windows editors write one) and white space
    // (CR included) do not count. Comments do: a file with a comment added is
    // judged by its probes, which still find every function NOT_STARTED.
    std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    std::string out;
    for (std::size_t i = start; i < text.size(); ++i)
        if (!std::isspace(static_cast<unsigned char>(text[i]))) out += text[i];
    return out;
}

bool isUnchangedStub(const std::filesystem::path& file, const ExerciseInfo& exercise) {
    const std::string* stub = shippedStub(exercise.file());
    std::error_code ec;
    constexpr std::uintmax_t kLargerThanAnyStub = 1 << 20;  // a bigger file is no stub; don't read it
    if (!stub || !std::filesystem::is_regular_file(file, ec) ||
        std::filesystem::file_size(file, ec) > kLargerThanAnyStub)
        return false;
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return normalisedGlsl(text.str()) == normalisedGlsl(*stub);
}

}  // namespace rl
