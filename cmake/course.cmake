# The course, read at configure time: every unit folder of course/ (one
# exercise each: unit.json, stub.glsl, solution.glsl, handout.md, probes.cpp,
# an optional reference.cpp, mutants/, alternatives/) and course/manifest.txt,
# the order and the selection. Nothing else in the build lists exercises.
#
# Sets, for CMakeLists.txt:
#   RAYLAB_UNITS               every unit folder name, the manifest's first, in its order
#   RAYLAB_COURSE              the manifest's units, in order
#   RAYLAB_OPTIONAL            those the manifest marks "optional"
#   RAYLAB_UNIT_PROBE_SOURCES  course/*/probes.cpp (the checks layer)
#   RAYLAB_UNIT_REFERENCE_SOURCES  course/*/reference.cpp (the reference layer)
# and writes into ${CMAKE_BINARY_DIR}/generated/:
#   course_units.cpp       the units' unit.json and stub.glsl, compiled in (course layer)
#   course_probes.cpp      each unit's probes by id (checks layer)
#   course_references.cpp  the units' light terms in double (reference layer)
# and, in the instructor's repository (where the units have solution.glsl),
# solutions/ at the root: a copy of the course's solutions, the folder that
# `--impl solutions` names (git ignores it).
#
# A change to any of these files re-runs CMake (CMAKE_CONFIGURE_DEPENDS).
#
# The browser edition's build (scripts/build-web.sh) runs it as a script:
#   cmake -DRAYLAB_ROOT_DIR=ROOT -DRAYLAB_GENERATED_DIR=DIR -P cmake/course.cmake
# and then also reads DIR/course_sources.txt (each unit's C++ file and the
# name the build gives its functions) and DIR/shipped-stubs/ (the stubs as
# NN-name.glsl).

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_minimum_required(VERSION 3.25)
endif()
if(NOT DEFINED RAYLAB_ROOT_DIR)
  set(RAYLAB_ROOT_DIR ${CMAKE_SOURCE_DIR})
endif()
if(NOT DEFINED RAYLAB_GENERATED_DIR)
  set(RAYLAB_GENERATED_DIR ${CMAKE_BINARY_DIR}/generated)
endif()
get_filename_component(RAYLAB_ROOT_DIR "${RAYLAB_ROOT_DIR}" ABSOLUTE)
get_filename_component(RAYLAB_GENERATED_DIR "${RAYLAB_GENERATED_DIR}" ABSOLUTE)
set(course_dir ${RAYLAB_ROOT_DIR}/course)
set(gen ${RAYLAB_GENERATED_DIR})
file(MAKE_DIRECTORY ${gen} ${gen}/shipped-stubs)
# Re-run CMake when a unit changes (not in script mode).
function(course_depends)
  if(NOT CMAKE_SCRIPT_MODE_FILE)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ARGN})
  endif()
endfunction()
function(course_symbol file symbol)
  if(NOT CMAKE_SCRIPT_MODE_FILE)
    set_source_files_properties(${file} PROPERTIES COMPILE_DEFINITIONS RL_UNIT_SYMBOL=${symbol})
  endif()
endfunction()
course_depends(${course_dir}/manifest.txt ${course_dir}/unit.schema.json)

# ---- every course file against course/unit.schema.json and the rules of
# cmake/validate_course.py: one line naming the file, line and field ----------------
find_program(RAYLAB_PYTHON3 NAMES python3)
if(NOT RAYLAB_PYTHON3)
  message(FATAL_ERROR "python3 is missing: the build checks the course's files with it (scripts/setup.sh installs it)")
endif()
execute_process(COMMAND ${RAYLAB_PYTHON3} ${CMAKE_CURRENT_LIST_DIR}/validate_course.py ${course_dir}
                RESULT_VARIABLE course_valid OUTPUT_VARIABLE course_problem ERROR_VARIABLE course_problem)
if(NOT course_valid EQUAL 0)
  string(STRIP "${course_problem}" course_problem)
  message(FATAL_ERROR " ${course_problem}")  # indented: CMake leaves the line as it is, unwrapped
endif()

# ---- the manifest ------------------------------------------------------------------
file(READ ${course_dir}/manifest.txt manifest_text)
string(REPLACE ";" "," manifest_text "${manifest_text}")  # no list separators inside a line
string(REPLACE "\r" "" manifest_text "${manifest_text}")
string(REPLACE "\n" ";" manifest_lines "${manifest_text}")  # empty lines kept: the line numbers count them
set(RAYLAB_COURSE "")
set(RAYLAB_OPTIONAL "")
set(line_number 0)
foreach(line IN LISTS manifest_lines)
  math(EXPR line_number "${line_number} + 1")
  string(REGEX REPLACE "#.*$" "" line "${line}")
  string(STRIP "${line}" line)
  if(line STREQUAL "")
    continue()
  endif()
  # "NN-name optional": an optional exercise (a bonus: checked and graded,
  # weight 0 by default, not in "N of N exercises pass"; course/README.md).
  set(optional FALSE)
  if(line MATCHES "^([^ \t]+)[ \t]+optional$")
    set(line "${CMAKE_MATCH_1}")
    set(optional TRUE)
  endif()
  if(NOT line MATCHES "^[0-9][0-9]-[a-z0-9-]+$")
    message(FATAL_ERROR "course/manifest.txt:${line_number}: \"${line}\" is no unit name (two digits, a dash, "
                        "lower-case letters, digits and dashes, like NN-name, optionally followed by \"optional\")")
  endif()
  if(NOT EXISTS ${course_dir}/${line}/unit.json)
    message(FATAL_ERROR "course/manifest.txt:${line_number}: no unit ${line} (course/${line}/unit.json is missing)")
  endif()
  if(line IN_LIST RAYLAB_COURSE)
    message(FATAL_ERROR "course/manifest.txt:${line_number}: ${line} is listed twice")
  endif()
  list(APPEND RAYLAB_COURSE ${line})
  if(optional)
    list(APPEND RAYLAB_OPTIONAL ${line})
  endif()
endforeach()
if(RAYLAB_COURSE STREQUAL "")
  message(FATAL_ERROR "course/manifest.txt lists no unit")
endif()

# ---- every unit folder: the course's first, then the others (their solutions
# are framework code) ----------------------------------------------------------------
if(CMAKE_SCRIPT_MODE_FILE)
  file(GLOB unit_jsons ${course_dir}/*/unit.json)
else()
  file(GLOB unit_jsons CONFIGURE_DEPENDS ${course_dir}/*/unit.json)
endif()
set(RAYLAB_UNITS ${RAYLAB_COURSE})
set(others "")
foreach(json IN LISTS unit_jsons)
  get_filename_component(dir ${json} DIRECTORY)
  get_filename_component(id ${dir} NAME)
  if(NOT id IN_LIST RAYLAB_COURSE)
    list(APPEND others ${id})
  endif()
endforeach()
list(SORT others)
list(APPEND RAYLAB_UNITS ${others})

set(RAYLAB_UNIT_PROBE_SOURCES "")
set(RAYLAB_UNIT_REFERENCE_SOURCES "")
set(unit_entries "")
set(probe_decls "")
set(probe_cases "")
set(reference_decls "")
set(reference_entries "")
set(source_lines "")
set(index 0)
foreach(id IN LISTS RAYLAB_UNITS)
  set(unit ${course_dir}/${id})
  string(REPLACE "-" "_" symbol "u${id}")
  list(FIND RAYLAB_COURSE ${id} position)
  foreach(required unit.json stub.glsl)
    if(NOT EXISTS ${unit}/${required})
      message(FATAL_ERROR "course/${id}/${required} is missing (every unit has one; docs/instructor.md, \"Adding an exercise\")")
    endif()
  endforeach()
  if(position EQUAL -1 AND NOT EXISTS ${unit}/solution.glsl)
    message(FATAL_ERROR "course/${id} is not in course/manifest.txt, so its solution.glsl is part of the framework, "
                        "but course/${id}/solution.glsl is missing")
  endif()
  course_depends(${unit}/unit.json ${unit}/stub.glsl)
  file(COPY_FILE ${unit}/stub.glsl ${gen}/shipped-stubs/${id}.glsl ONLY_IF_DIFFERENT)
  file(READ ${unit}/unit.json json)
  file(READ ${unit}/stub.glsl stub)
  # Its JSON checked here, so that a mistake stops the build naming the file
  # (the program reads every field again, app/course/exercise_registry.cpp).
  foreach(field title functions)
    string(JSON value ERROR_VARIABLE json_error GET "${json}" ${field})
    if(json_error)
      message(FATAL_ERROR "course/${id}/unit.json: ${json_error}")
    endif()
  endforeach()
  foreach(text IN ITEMS json stub)
    string(FIND "${${text}}" ")rl_unit\"" clash)
    if(NOT clash EQUAL -1)
      message(FATAL_ERROR "course/${id}: a file holds the text )rl_unit\" that the build quotes it with")
    endif()
  endforeach()
  if(id IN_LIST RAYLAB_OPTIONAL)
    set(unit_optional true)
  else()
    set(unit_optional false)
  endif()
  string(APPEND unit_entries "    {\"${id}\", ${position}, R\"rl_unit(${json})rl_unit\", R\"rl_unit(${stub})rl_unit\", ${unit_optional}},\n")
  if(EXISTS ${unit}/probes.cpp)
    list(APPEND RAYLAB_UNIT_PROBE_SOURCES ${unit}/probes.cpp)
    course_symbol(${unit}/probes.cpp ${symbol})
    string(APPEND source_lines "${unit}/probes.cpp ${symbol}\n")
    string(APPEND probe_decls "std::vector<ProbeSpec> unitProbes_${symbol}();\n")
    string(APPEND probe_cases "    if (id == \"${id}\") return unitProbes_${symbol}();\n")
  elseif(EXISTS ${unit}/probes.json)
    # A student edition: the probes as the instructor's build recorded them
    # (checks/probe_data.h), compiled in; no probes.cpp, no reference.
    course_depends(${unit}/probes.json)
    file(READ ${unit}/probes.json record)
    string(FIND "${record}" ")rl_probes\"" clash)
    if(NOT clash EQUAL -1)
      message(FATAL_ERROR "course/${id}/probes.json: holds the text )rl_probes\" that the build quotes it with")
    endif()
    # In pieces: a compiler may limit one string literal (MSVC: 16 KB); adjacent ones join.
    string(LENGTH "${record}" record_length)
    set(pieces "")
    set(at 0)
    while(at LESS record_length)
      string(SUBSTRING "${record}" ${at} 8000 piece)
      string(APPEND pieces "    R\"rl_probes(${piece})rl_probes\"\n")
      math(EXPR at "${at} + 8000")
    endwhile()
    string(APPEND probe_decls "const char* const kRecordedProbes_${symbol} =\n${pieces};\n")
    string(APPEND probe_cases "    if (id == \"${id}\") return probesFromRecord(kRecordedProbes_${symbol}, \"course/${id}/probes.json\");\n")
  endif()
  if(EXISTS ${unit}/reference.cpp)
    list(APPEND RAYLAB_UNIT_REFERENCE_SOURCES ${unit}/reference.cpp)
    course_symbol(${unit}/reference.cpp ${symbol})
    string(APPEND source_lines "${unit}/reference.cpp ${symbol}\n")
    string(FIND "${json}" "\"light\"" has_light)
    if(NOT has_light EQUAL -1)
      string(APPEND reference_decls "glm::dvec3 unitLight_${symbol}(const UnitLightInputs& at);\n")
      string(APPEND reference_entries "        {\"${id}\", &unitLight_${symbol}},\n")
    endif()
  endif()
  math(EXPR index "${index} + 1")
endforeach()

function(write_generated name text)
  file(WRITE ${gen}/${name}.tmp "${text}")
  file(COPY_FILE ${gen}/${name}.tmp ${gen}/${name} ONLY_IF_DIFFERENT)
  file(REMOVE ${gen}/${name}.tmp)
endfunction()

write_generated(course_sources.txt "${source_lines}")
file(GLOB stale_stubs ${gen}/shipped-stubs/*.glsl)
foreach(id IN LISTS RAYLAB_UNITS)
  list(REMOVE_ITEM stale_stubs ${gen}/shipped-stubs/${id}.glsl)
endforeach()
if(stale_stubs)
  file(REMOVE ${stale_stubs})
endif()

write_generated(course_units.cpp "// Written by cmake/course.cmake from course/: do not edit.
#include \"course/unit_sources.h\"

namespace rl {

const std::vector<UnitSource>& unitSources() {
    static const std::vector<UnitSource> units = {
${unit_entries}    };
    return units;
}

}  // namespace rl
")

write_generated(course_probes.cpp "// Written by cmake/course.cmake from course/*/probes.cpp (or probes.json): do not edit.
#include \"checks/probe_cases.h\"
#include \"checks/probe_data.h\"

namespace rl {

${probe_decls}
std::vector<ProbeSpec> unitProbes(const std::string& id) {
${probe_cases}    return {};
}

}  // namespace rl
")

write_generated(course_references.cpp "// Written by cmake/course.cmake from course/*/reference.cpp: do not edit.
#include \"reference/unit_light.h\"

namespace rl::ref {

${reference_decls}
const std::vector<UnitLightTerm>& unitLightTerms() {
    static const std::vector<UnitLightTerm> terms = {
${reference_entries}    };
    return terms;
}

}  // namespace rl::ref
")

# ---- solutions/: the course's solutions as one folder (instructor's repository) ----
set(have_solutions FALSE)
foreach(id IN LISTS RAYLAB_COURSE)
  if(EXISTS ${course_dir}/${id}/solution.glsl)
    set(have_solutions TRUE)
  endif()
endforeach()
set(RAYLAB_COURSE_HAS_SOLUTIONS ${have_solutions})
if(have_solutions)
  file(MAKE_DIRECTORY ${RAYLAB_ROOT_DIR}/solutions)
  # First what is no exercise any more (taken out of the manifest), then the copies.
  file(GLOB stale ${RAYLAB_ROOT_DIR}/solutions/*.glsl)
  foreach(id IN LISTS RAYLAB_COURSE)
    list(REMOVE_ITEM stale ${RAYLAB_ROOT_DIR}/solutions/${id}.glsl)
  endforeach()
  if(stale)
    file(REMOVE ${stale})
  endif()
  foreach(id IN LISTS RAYLAB_COURSE)
    set(solution ${course_dir}/${id}/solution.glsl)
    if(EXISTS ${solution})
      course_depends(${solution})
      file(COPY_FILE ${solution} ${RAYLAB_ROOT_DIR}/solutions/${id}.glsl ONLY_IF_DIFFERENT)
    endif()
  endforeach()
endif()
