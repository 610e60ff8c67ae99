# Installs this build (vrlis, vrlis::integration, vrlis::scenes) into a scratch prefix, then
# configures the lab (bench/) as a project of its own against it and builds one of its tools:
# the lab needs nothing of the tree but the installed package.
include(${CMAKE_CURRENT_LIST_DIR}/run_step.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
# Unoptimised (Release without -O3): what is checked is that the tool configures, compiles
# and links on the package alone; the in-tree build compiles the same source optimised, and
# -O3 here cost the test suite ~15 s of CPU.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/bench -B ${WORK_DIR}/build -G Ninja -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_FLAGS_RELEASE=-DNDEBUG -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build --target ${TARGET})
