// A unit's probes as data: what the checker needs from the double-precision
// reference, recorded by the instructor's build, so that a student edition
// checks with the same cases, expected values, tolerances and recognised
// mistakes without the reference's sources or the mistakes' formulas
// (docs/instructor.md, "A student edition"; docs/decisions.md, "What the
// student edition ships").
//
// The record of a unit is JSON: every ProbeSpec with its cases' inputs and
// groups and, per case, the expected value, the tolerance, the described
// inputs and each mistake's value. Doubles are written so that they read back
// bit for bit (nlohmann's shortest round-trip form; NaN and infinities as the
// strings "nan", "inf", "-inf"), so a recorded unit gives the same verdict
// and hint as its probes.cpp on every file.
#pragma once

#include "checks/probe_cases.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace rl {

// The record of `specs` (one unit's probes).
nlohmann::json recordProbes(const std::vector<ProbeSpec>& specs);

// The probes of a record written by recordProbes(); `origin` names it in
// errors ("course/05-ggx/probes.json: ..."), one line each.
std::vector<ProbeSpec> probesFromRecord(const std::string& text, const std::string& origin);

}  // namespace rl
