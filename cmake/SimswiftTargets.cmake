# simswift_library(NAME DIR): one static library per source folder, named
# simswift::NAME, made of every .cpp below DIR (new files need no CMake edit).
function(simswift_library name dir)
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
  if(NOT srcs)
    # A folder not written yet still gets a real (empty) library, so that
    # target_link_libraries(... PUBLIC ...) on it stays valid.
    set(stub ${PROJECT_BINARY_DIR}/simswift_${name}_empty.cpp)
    file(WRITE ${stub} "// empty: ${dir} has no sources yet\n")
    set(srcs ${stub})
  endif()
  add_library(simswift_${name} STATIC ${srcs})
  target_include_directories(simswift_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>)
  add_library(simswift::${name} ALIAS simswift_${name})
endfunction()

# simswift_forbid_includes(DIR PREFIX [EXCEPT PATH...]): fail the configure
# step if any file under DIR (every .cpp and .hpp, at any depth) includes a
# header under PREFIX (from the source root, or by a relative path:
# "../PREFIX..."). EXCEPT: files ("app/simswift_agent.cpp") or folders
# ("sim/programs/", with the slash) of DIR left out, from the source root.
# Used to keep agent/ (the robot code) free of the simulator, so the same code
# runs on a robot, and the simulator's files other than sim/programs free of
# the robot program.
function(simswift_forbid_includes dir prefix)
  simswift_wall_files(files ${dir} ${ARGN})
  foreach(f ${files})
    file(STRINGS ${f} hits REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<](\\.\\./)*${prefix}")
    if(hits)
      message(FATAL_ERROR "${f} includes ${hits}: ${dir}/ must not depend on ${prefix}")
    endif()
  endforeach()
endfunction()

# simswift_forbid_namespace(DIR NS [EXCEPT PATH...]): the same for code that
# names the C++ namespace NS (`NS::`, outside // comments): a header of an
# allowed folder may declare something of NS, but DIR's files call it only
# through that folder's own names (a use the include check cannot see).
function(simswift_forbid_namespace dir ns)
  simswift_wall_files(files ${dir} ${ARGN})
  foreach(f ${files})
    file(STRINGS ${f} lines REGEX "${ns}::")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "//.*$" "" code "${line}")
      if(code MATCHES "(^|[^A-Za-z0-9_])${ns}::")
        string(STRIP "${line}" line)
        message(FATAL_ERROR "${f} names ${ns}:: (\"${line}\"): ${dir}/ must not depend on ${ns}")
      endif()
    endforeach()
  endforeach()
endfunction()

# The files simswift_forbid_includes and _namespace check: DIR's .cpp and
# .hpp but those under an EXCEPT path.
function(simswift_wall_files out dir)
  cmake_parse_arguments(PARSE_ARGV 2 wall "" "" "EXCEPT")
  set(depends CONFIGURE_DEPENDS)  # a new file re-runs the check at build time
  if(CMAKE_SCRIPT_MODE_FILE)
    set(depends)  # (cmake -P: tests/cmake)
  endif()
  file(GLOB_RECURSE files ${depends}
       ${PROJECT_SOURCE_DIR}/${dir}/*.cpp ${PROJECT_SOURCE_DIR}/${dir}/*.hpp)
  set(kept)
  foreach(f ${files})
    file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${f})
    set(skip OFF)
    foreach(e ${wall_EXCEPT})
      string(LENGTH "${e}" n)
      string(SUBSTRING "${rel}" 0 ${n} head)
      if(rel STREQUAL e OR (e MATCHES "/$" AND head STREQUAL e))
        set(skip ON)
      endif()
    endforeach()
    if(NOT skip)
      list(APPEND kept ${f})
    endif()
  endforeach()
  set(${out} ${kept} PARENT_SCOPE)
endfunction()

# The robot program's wall: of the simulator (sim/), what is built on it
# (app/), the public API (include/) and its Python module (python/), only
# sim/programs (what drives a robot's body) and app/simswift_agent.cpp (the
# builtin robot program's own main: simswift-agent IS the robot program)
# include agent/ or name agent::. Everything else reaches the robot program
# through sim/programs' own names. tests/cmake/test_agent_wall.cmake runs it
# on made-up trees.
function(simswift_agent_wall)
  foreach(dir sim app include python)
    simswift_forbid_includes(${dir} "agent/" EXCEPT sim/programs/ app/simswift_agent.cpp)
    simswift_forbid_namespace(${dir} agent EXCEPT sim/programs/ app/simswift_agent.cpp)
  endforeach()
endfunction()

# simswift_test(NAME DIR LIBS...): one GoogleTest executable per tests/ folder.
function(simswift_test name dir)
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
  if(NOT srcs)
    return()
  endif()
  add_executable(test_${name} ${srcs})
  target_link_libraries(test_${name} PRIVATE ${ARGN} GTest::gtest_main)
  target_compile_definitions(test_${name} PRIVATE
      SIMSWIFT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
      SIMSWIFT_BINARY_DIR="${PROJECT_BINARY_DIR}")
  gtest_discover_tests(test_${name} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${name})
endfunction()
