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

# simswift_forbid_includes(DIR PREFIX): fail the configure step if any file
# under DIR includes a header under PREFIX (from the source root, or by a
# relative path: "../PREFIX..."). Used to keep agent/ (the robot code) free
# of the simulator, so the same code runs on a robot, and the simulator's
# folders other than sim/programs free of the robot program.
function(simswift_forbid_includes dir prefix)
  file(GLOB_RECURSE files CONFIGURE_DEPENDS
       ${PROJECT_SOURCE_DIR}/${dir}/*.cpp ${PROJECT_SOURCE_DIR}/${dir}/*.hpp)
  foreach(f ${files})
    file(STRINGS ${f} hits REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<](\\.\\./)*${prefix}")
    if(hits)
      message(FATAL_ERROR "${f} includes ${hits}: ${dir}/ must not depend on ${prefix}")
    endif()
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
