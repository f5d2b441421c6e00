#include "checks/probe_data.h"

#include "core/error.h"
#include "core/json_text.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <map>
#include <memory>

namespace rl {

using nlohmann::json;

namespace {

json number(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return x;
}

double numberFrom(const json& j, const std::string& origin) {
    if (j.is_number()) return j.get<double>();
    if (j.is_string()) {
        const std::string s = j.get<std::string>();
        if (s == "nan") return std::nan("");
        if (s == "inf") return HUGE_VAL;
        if (s == "-inf") return -HUGE_VAL;
    }
    throw Error(origin + ": " + describeJsonValue(j) + " is no recorded number");
}

json value3(const ProbeValue& v) { return json::array({number(v[0]), number(v[1]), number(v[2])}); }

ProbeValue value3From(const json& j, const std::string& origin) {
    if (!j.is_array() || j.size() != 3) throw Error(origin + ": a value is not 3 numbers");
    return {numberFrom(j[0], origin), numberFrom(j[1], origin), numberFrom(j[2], origin)};
}

// The key by which a recorded spec finds a case's row: its inputs' bytes and group.
std::string caseKey(const ProbeCase& c) {
    std::string key(sizeof c.in, '\0');
    std::memcpy(key.data(), c.in.data(), sizeof c.in);
    return key + c.group;
}

// The recorded rows of one spec, shared by its functions.
struct Rows {
    std::map<std::string, std::size_t> index;
    std::vector<ProbeValue> expected;
    std::vector<std::pair<double, double>> tolerance;
    std::vector<std::string> described;
    std::vector<std::vector<ProbeValue>> mistakes;  // [mistake][case]
    std::size_t row(const ProbeCase& c) const {
        auto it = index.find(caseKey(c));
        if (it == index.end()) throw Error("a probe case that is not in the recorded probes");
        return it->second;
    }
};

const json& field(const json& j, const char* name, const std::string& origin) {
    if (!j.is_object() || !j.contains(name)) throw Error(origin + ": no field \"" + name + "\"");
    return j.at(name);
}

}  // namespace

json recordProbes(const std::vector<ProbeSpec>& specs) {
    json out = json::array();
    for (const ProbeSpec& s : specs) {
        json j;
        j["name"] = s.name;
        if (s.programFunction) j["program_function"] = *s.programFunction;
        j["signature"] = s.signature;
        j["outputs"] = s.outputs;
        j["needs_scene"] = s.needsScene;
        j["group_hints"] = json::array();
        for (const auto& [group, hint] : s.groupHints) j["group_hints"].push_back({group, hint});
        j["mistakes"] = json::array();
        for (const KnownMistake& m : s.mistakes) {
            json values = json::array();
            for (const ProbeCase& c : s.cases) values.push_back(value3(m.compute(c)));
            j["mistakes"].push_back({{"symptom", m.symptom}, {"hint", m.hint}, {"values", values}});
        }
        j["cases"] = json::array();
        for (const ProbeCase& c : s.cases) {
            json in = json::array();
            for (float x : c.in) in.push_back(number(double(x)));
            const auto tol = s.tolerance(c);
            j["cases"].push_back({{"in", in},
                                  {"group", c.group},
                                  {"expected", value3(s.expected(c))},
                                  {"tolerance", json::array({number(tol.first), number(tol.second)})},
                                  {"described", s.describe(c)}});
        }
        out.push_back(j);
    }
    return out;
}

std::vector<ProbeSpec> probesFromRecord(const std::string& text, const std::string& origin) {
    const json record = parseJsonText(text, origin);
    if (!record.is_array()) throw Error(origin + ": not a list of recorded probes");
    std::vector<ProbeSpec> specs;
    try {
        for (const json& j : record) {
            ProbeSpec s{field(j, "name", origin).get<std::string>(), field(j, "signature", origin).get<std::string>(),
                        field(j, "outputs", origin).get<int>()};
            if (j.contains("program_function")) s.programFunction = j.at("program_function").get<int>();
            s.needsScene = field(j, "needs_scene", origin).get<bool>();
            for (const json& g : field(j, "group_hints", origin))
                s.groupHints.emplace_back(g.at(0).get<std::string>(), g.at(1).get<std::string>());
            auto rows = std::make_shared<Rows>();
            for (const json& c : field(j, "cases", origin)) {
                ProbeCase pc;
                const json& in = field(c, "in", origin);
                if (!in.is_array() || in.size() != pc.in.size()) throw Error(origin + ": a case has no " +
                                                                             std::to_string(pc.in.size()) + " inputs");
                for (std::size_t k = 0; k < pc.in.size(); ++k) pc.in[k] = float(numberFrom(in[k], origin));
                pc.group = field(c, "group", origin).get<std::string>();
                rows->index.emplace(caseKey(pc), s.cases.size());
                rows->expected.push_back(value3From(field(c, "expected", origin), origin));
                const json& tol = field(c, "tolerance", origin);
                rows->tolerance.emplace_back(numberFrom(tol.at(0), origin), numberFrom(tol.at(1), origin));
                rows->described.push_back(field(c, "described", origin).get<std::string>());
                s.cases.push_back(pc);
            }
            for (const json& m : field(j, "mistakes", origin)) {
                std::vector<ProbeValue> values;
                for (const json& v : field(m, "values", origin)) values.push_back(value3From(v, origin));
                if (values.size() != s.cases.size()) throw Error(origin + ": a mistake's values do not match the cases");
                const std::size_t at = rows->mistakes.size();
                rows->mistakes.push_back(std::move(values));
                s.mistakes.push_back({field(m, "symptom", origin).get<std::string>(),
                                      field(m, "hint", origin).get<std::string>(),
                                      [rows, at](const ProbeCase& c) { return rows->mistakes[at][rows->row(c)]; }});
            }
            s.expected = [rows](const ProbeCase& c) { return rows->expected[rows->row(c)]; };
            s.tolerance = [rows](const ProbeCase& c) { return rows->tolerance[rows->row(c)]; };
            s.describe = [rows](const ProbeCase& c) { return rows->described[rows->row(c)]; };
            specs.push_back(std::move(s));
        }
    } catch (const json::exception& e) {
        throw Error(origin + ": not a probe record (" + e.what() + ")");
    }
    return specs;
}

}  // namespace rl
