# Installs vrlis into a scratch prefix, then configures and builds a consumer project that
# finds it with find_package(vrlis) and compiles the README's usage example, and runs it.
file(REMOVE_RECURSE ${WORK_DIR})
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
endfunction()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -DCMAKE_CXX_COMPILER=${CXX} -DVRLIS_BUILD_TESTS=OFF
    -DVRLIS_BUILD_BENCH=OFF -DVRLIS_BUILD_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${WORK_DIR}/build)

# The README's example is the consumer's main.cpp: the snippet users copy is the one we compile.
file(READ ${SOURCE_DIR}/README.md readme)
string(REGEX MATCH "<!-- usage-example -->[\r\n]+```cpp[\r\n]+(.*)```[\r\n]+<!-- /usage-example -->" _ "${readme}")
if(NOT CMAKE_MATCH_1)
  message(FATAL_ERROR "README.md has no usage example between the usage-example markers")
endif()
file(COPY ${SOURCE_DIR}/tests/consumer/project/ DESTINATION ${WORK_DIR}/project)
file(WRITE ${WORK_DIR}/project/main.cpp "${CMAKE_MATCH_1}")

run(${CMAKE_COMMAND} -S ${WORK_DIR}/project -B ${WORK_DIR}/project-build -DCMAKE_CXX_COMPILER=${CXX}
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/project-build)
run(${WORK_DIR}/project-build/consumer)
