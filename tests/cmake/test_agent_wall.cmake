# The robot program's wall (cmake/SimswiftTargets.cmake, simswift_agent_wall)
# on made-up source trees: every file of sim/, app/, include/ and python/ is
# checked, top-level files too; only sim/programs/ and app/simswift_agent.cpp
# may include agent/ or name agent::.
#   cmake -DTARGETS=<cmake/SimswiftTargets.cmake> -DWORK=<scratch dir> -P test_agent_wall.cmake
# (with -DCASE=<name>: runs the wall on WORK/<name> alone; configure's
# FATAL_ERROR ends that process, so each case runs in its own.)
cmake_minimum_required(VERSION 3.20)
if(DEFINED CASE)
  set(PROJECT_SOURCE_DIR ${WORK}/${CASE})
  include(${TARGETS})
  simswift_agent_wall()
  return()
endif()

# Every tree holds what is allowed; a failing case adds one offending file.
function(allowed_tree root)
  file(WRITE ${root}/sim/programs/Programs.cpp "#include \"agent/program/RobotProgram.hpp\"\nusing T = agent::program::Threading;\n")
  file(WRITE ${root}/app/simswift_agent.cpp "#include \"agent/program/RobotSetup.hpp\"\nnamespace ap = agent::program;\n")
  file(WRITE ${root}/sim/views/View.hpp "// as agent::behaviour::PositionalDistribution (a comment names it)\n")
  file(WRITE ${root}/sim/runner/Runner.cpp "#include \"common/libagent/Names.hpp\"\nauto n = common::libagent::kJoints;\n")
  file(WRITE ${root}/app/api/Sim.cpp "#include \"sim/programs/Programs.hpp\"\nauto t = programs::Threading::Inline;\n")
endfunction()

# case name; file (from the tree's root) or "" for the allowed tree alone; its text
set(cases
  "allowed|-|-"
  "app_top_level_include|app/other_main.cpp|#include \"agent/program/RobotSetup.hpp\""
  "sim_calls_agent|sim/runner/Scenario.cpp|  agent::program::readActions(robot, rs.setup)\;"
  "app_names_agent|app/api/Simulation.cpp|run.setThreading(agent::program::Threading::Inline)\;"
  "relative_include|app/api/Api.cpp|#include \"../../agent/motion/Walk.hpp\""
  "public_header|include/simswift/Robot.hpp|#  include <agent/blackboard/Blackboard.hpp>"
  "python_module|python/module.cpp|#include \"agent/program/RobotProgram.hpp\""
  "folder_named_like_programs|sim/programs_extra/X.cpp|#include \"agent/program/RobotProgram.hpp\""
  "global_qualified|sim/world/World.cpp|auto x = ::agent::motion::kStep\;"
)
set(failures 0)
foreach(c IN LISTS cases)
  string(REPLACE "|" ";" parts "${c}")
  list(GET parts 0 name)
  list(GET parts 1 file)
  list(GET parts 2 text)
  file(REMOVE_RECURSE ${WORK}/${name})
  allowed_tree(${WORK}/${name})
  if(NOT file STREQUAL "-")
    file(WRITE ${WORK}/${name}/${file} "${text}\n")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -DTARGETS=${TARGETS} -DWORK=${WORK} -DCASE=${name}
                          -P ${CMAKE_CURRENT_LIST_FILE}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(file STREQUAL "-")
    if(NOT rc EQUAL 0)
      message(SEND_ERROR "${name}: the allowed tree was refused:\n${out}")
      math(EXPR failures "${failures} + 1")
    endif()
  elseif(rc EQUAL 0)
    message(SEND_ERROR "${name}: ${file} (\"${text}\") passed the wall")
    math(EXPR failures "${failures} + 1")
  else()
    string(REGEX REPLACE "[ \n]+" " " flat "${out}")
    if(NOT flat MATCHES "${name}/${file}")
      message(SEND_ERROR "${name}: refused without naming ${file}:\n${out}")
      math(EXPR failures "${failures} + 1")
    endif()
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "${failures} case(s) failed")
endif()
message(STATUS "agent wall: every case as expected")
