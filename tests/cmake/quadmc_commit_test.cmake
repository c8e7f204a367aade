# Tests of cmake/quadmc_commit.cmake, the build-time lookup of the commit `quadmc --version` and
# meta.csv name. Run by CTest (tests/CMakeLists.txt) in script mode:
#   cmake -DSCRIPT=<cmake/quadmc_commit.cmake> -DWORK=<scratch folder> [-DGIT=<git>] -P <this>
# Without GIT only the cases that need no git run (the CTest test without_git); with it, a
# repository of its own is made in a scratch folder outside any checkout, so the expected commit
# is the one this test made, whatever the source tree is (a checkout, a tarball, dirty or not).
cmake_minimum_required(VERSION 3.25)

if(NOT SCRIPT OR NOT WORK)
  message(FATAL_ERROR "pass -DSCRIPT=<quadmc_commit.cmake> -DWORK=<scratch folder>")
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# git never looks above WORK for a repository, so "not a checkout" holds wherever WORK is.
set(ENV{GIT_CEILING_DIRECTORIES} "${WORK}")

set(failures 0)

# The commit the script writes for SOURCE_DIR with the given git ("" for none).
function(commit_of source_dir git out)
  set(header "${WORK}/quadmc_commit.hpp")
  file(REMOVE "${header}")
  execute_process(
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${source_dir} -DOUTPUT=${header}
            -DGIT_EXECUTABLE=${git} -P ${SCRIPT}
    RESULT_VARIABLE status ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "quadmc_commit.cmake failed (${status}) for ${source_dir}: ${errors}")
  endif()
  file(READ "${header}" text)
  if(NOT text MATCHES "#define QUADMC_COMMIT \"([^\"]*)\"")
    message(FATAL_ERROR "no QUADMC_COMMIT in the header: ${text}")
  endif()
  set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

function(expect what actual expected)
  if(actual STREQUAL expected)
    message(STATUS "ok: ${what}: ${actual}")
  else()
    message(SEND_ERROR "${what}: got '${actual}', expected '${expected}'")
    math(EXPR n "${failures} + 1")
    set(failures ${n} PARENT_SCOPE)
  endif()
endfunction()

function(git_in dir)
  execute_process(COMMAND ${GIT} -C ${dir} ${ARGN} RESULT_VARIABLE status
                  OUTPUT_VARIABLE output ERROR_VARIABLE errors OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "git ${ARGN} in ${dir} failed: ${errors}")
  endif()
  set(git_output "${output}" PARENT_SCOPE)
endfunction()

# The source folder of a tarball: files, no repository.
set(tarball "${WORK}/tarball")
file(WRITE "${tarball}/CMakeLists.txt" "project(x)\n")

# Without git, whatever the folder is: "unknown", and the build goes on.
commit_of("${tarball}" "" commit)
expect("no git given" "${commit}" "unknown")
commit_of("${tarball}" "${WORK}/no/such/git" commit)
expect("git given but not installed" "${commit}" "unknown")

if(GIT)
  commit_of("${tarball}" "${GIT}" commit)
  expect("not a checkout" "${commit}" "unknown")

  set(checkout "${WORK}/checkout")
  file(WRITE "${checkout}/code.cpp" "int main() {}\n")
  file(WRITE "${checkout}/sub/notes.txt" "notes\n")
  file(WRITE "${checkout}/results/default/README.md" "# Results\n")
  git_in("${checkout}" -c init.defaultBranch=main init -q)
  git_in("${checkout}" add .)
  git_in("${checkout}" -c user.name=test -c user.email=test@example.invalid
         -c commit.gpgsign=false commit -q -m "one commit")
  git_in("${checkout}" rev-parse HEAD)
  set(head "${git_output}")

  commit_of("${checkout}" "${GIT}" commit)
  expect("clean checkout" "${commit}" "${head}")
  if(NOT head MATCHES "^[0-9a-f]+$")
    message(SEND_ERROR "git rev-parse HEAD gave '${head}'")
    math(EXPR failures "${failures} + 1")
  endif()

  # A source folder inside someone else's checkout is not that checkout's commit.
  commit_of("${checkout}/sub" "${GIT}" commit)
  expect("folder inside another checkout" "${commit}" "unknown")

  # The results a run rewrites do not make the code dirty; a changed or new source file does.
  file(WRITE "${checkout}/results/default/README.md" "# Results, regenerated\n")
  file(WRITE "${checkout}/results/new/meta.csv" "quadmc_version\n")
  commit_of("${checkout}" "${GIT}" commit)
  expect("only results/ changed" "${commit}" "${head}")

  file(WRITE "${checkout}/code.cpp" "int main() { return 1; }\n")
  commit_of("${checkout}" "${GIT}" commit)
  expect("tracked file changed" "${commit}" "${head}-dirty")
  git_in("${checkout}" checkout -q -- code.cpp)

  file(WRITE "${checkout}/new.cpp" "int f() { return 0; }\n")
  commit_of("${checkout}" "${GIT}" commit)
  expect("untracked file added" "${commit}" "${head}-dirty")
  file(REMOVE "${checkout}/new.cpp")

  commit_of("${checkout}" "${GIT}" commit)
  expect("clean again" "${commit}" "${head}")
endif()

file(REMOVE_RECURSE "${WORK}")
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} case(s) of quadmc_commit.cmake failed")
endif()
