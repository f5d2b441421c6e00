# Run at build time (cmake -P): compiles the shipped exercise stubs into the
# program, so that `raylab check` recognises "the unchanged stub" by what was
# shipped, never by the live exercises/ folder (which is the student's work).
#
#   cmake -DEXERCISES_DIR=... -DSNAPSHOT_DIR=... -DOUTPUT=shipped_stubs.cpp -P shipped_stubs.cmake
#
# A file of exercises/ is taken as a stub only while it still looks like one:
# every function body is `return ...NOT_STARTED...;`. A student who edited
# exercises/ in place and then rebuilds keeps the stub of the previous build
# (the copy in SNAPSHOT_DIR); an instructor who changes a stub gets the new one.
cmake_minimum_required(VERSION 3.25)

file(GLOB stubs RELATIVE ${EXERCISES_DIR} ${EXERCISES_DIR}/*.glsl)
list(SORT stubs)
file(MAKE_DIRECTORY ${SNAPSHOT_DIR})

set(entries "")
set(arrays "")
set(index 0)
foreach(name IN LISTS stubs)
  file(READ ${EXERCISES_DIR}/${name} text)
  # Rough normal form for the test below only: no // comments, no white space.
  string(REGEX REPLACE "//[^\n]*" "" code "${text}")
  string(REGEX REPLACE "[ \t\r\n]" "" code "${code}")
  string(REGEX REPLACE "{return[A-Za-z0-9_]*\\(?NOT_STARTED\\)?;}" "" rest "${code}")
  string(FIND "${rest}" "{" brace)
  if(brace EQUAL -1 AND NOT code STREQUAL "")
    file(COPY_FILE ${EXERCISES_DIR}/${name} ${SNAPSHOT_DIR}/${name} ONLY_IF_DIFFERENT)
  elseif(EXISTS ${SNAPSHOT_DIR}/${name})
    message(STATUS "exercises/${name} is no stub any more (edited?): keeping the stub of the previous build")
  else()
    message(STATUS "exercises/${name} is no stub (edited before the first build?): "
                   "`raylab check` will judge it by its probes alone")
    continue()
  endif()
  file(READ ${SNAPSHOT_DIR}/${name} bytes HEX)
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${bytes}")
  string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n    " bytes "${bytes}")
  string(APPEND arrays "const unsigned char kStub${index}[] = {\n    ${bytes}};\n")
  string(APPEND entries "        {\"${name}\", std::string(reinterpret_cast<const char*>(kStub${index}), sizeof kStub${index})},\n")
  math(EXPR index "${index} + 1")
endforeach()

set(source "// Generated at build time by cmake/shipped_stubs.cmake from exercises/: do not edit.
#include \"course/exercise_registry.h\"

#include <map>

namespace rl {
namespace {
${arrays}}  // namespace

const std::string* shippedStub(const std::string& fileName) {
    static const std::map<std::string, std::string> stubs = {
${entries}    };
    auto it = stubs.find(fileName);
    return it == stubs.end() ? nullptr : &it->second;
}

}  // namespace rl
")
file(WRITE ${OUTPUT}.tmp "${source}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
