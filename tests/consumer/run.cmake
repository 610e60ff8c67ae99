# Installs vrlis into a scratch prefix, then configures and builds a consumer project that
# finds it with find_package(vrlis), compiles the C++ blocks of the README and of
# docs/porting.md, and runs them.
include(${CMAKE_CURRENT_LIST_DIR}/run_step.cmake)
file(REMOVE_RECURSE ${WORK_DIR})

run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_CXX_COMPILER=${CXX} -DVRLIS_BUILD_TESTS=OFF
    -DVRLIS_BUILD_BENCH=OFF -DVRLIS_BUILD_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${WORK_DIR}/build)

# Every C++ block of the README and of docs/porting.md is one of the consumer's programs: the
# snippets users copy are the ones we compile and run. Each is a whole program.
file(COPY ${SOURCE_DIR}/tests/consumer/project/ DESTINATION ${WORK_DIR}/project)
set(programs "")
foreach(page README.md docs/porting.md)
  file(READ ${SOURCE_DIR}/${page} text)
  get_filename_component(stem ${page} NAME_WE)
  string(TOLOWER ${stem} stem)
  # Walked with string(FIND), not a regex list: the code's semicolons would split a list.
  set(n 0)
  string(FIND "${text}" "```cpp\n" open)
  while(NOT open EQUAL -1)
    math(EXPR open "${open} + 7")
    string(SUBSTRING "${text}" ${open} -1 text)
    string(FIND "${text}" "```" close)
    string(SUBSTRING "${text}" 0 ${close} code)
    math(EXPR n "${n} + 1")
    file(WRITE ${WORK_DIR}/project/examples/${stem}_${n}.cpp "${code}")
    list(APPEND programs ${stem}_${n})
    math(EXPR close "${close} + 3")
    string(SUBSTRING "${text}" ${close} -1 text)
    string(FIND "${text}" "```cpp\n" open)
  endwhile()
  if(n EQUAL 0)
    message(FATAL_ERROR "${page} has no C++ block")
  endif()
endforeach()

run(${CMAKE_COMMAND} -S ${WORK_DIR}/project -B ${WORK_DIR}/project-build -DCMAKE_CXX_COMPILER=${CXX}
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/project-build)
foreach(program IN LISTS programs)
  run(${WORK_DIR}/project-build/${program})
endforeach()
