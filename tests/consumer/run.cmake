# Installs vrlis into a scratch prefix, then configures and builds a consumer project that
# finds it with find_package(vrlis) and compiles the README's usage example, and runs it.
include(${CMAKE_CURRENT_LIST_DIR}/run_step.cmake)
file(REMOVE_RECURSE ${WORK_DIR})

run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_CXX_COMPILER=${CXX} -DVRLIS_BUILD_TESTS=OFF
    -DVRLIS_BUILD_BENCH=OFF -DVRLIS_BUILD_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${WORK_DIR}/build)

# The README's examples are the consumer's programs: the snippets users copy are the ones we compile.
file(READ ${SOURCE_DIR}/README.md readme)
file(COPY ${SOURCE_DIR}/tests/consumer/project/ DESTINATION ${WORK_DIR}/project)
foreach(example usage gather)
  string(REGEX MATCH "<!-- ${example}-example -->[\r\n]+```cpp[\r\n]+([^`]*)```[\r\n]+<!-- /${example}-example -->" _ "${readme}")
  if(NOT CMAKE_MATCH_1)
    message(FATAL_ERROR "README.md has no ${example} example between the ${example}-example markers")
  endif()
  file(WRITE ${WORK_DIR}/project/${example}.cpp "${CMAKE_MATCH_1}")
endforeach()

run(${CMAKE_COMMAND} -S ${WORK_DIR}/project -B ${WORK_DIR}/project-build -DCMAKE_CXX_COMPILER=${CXX}
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/project-build)
run(${WORK_DIR}/project-build/usage)
run(${WORK_DIR}/project-build/gather)
