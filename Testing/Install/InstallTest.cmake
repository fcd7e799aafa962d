# The module as a user gets it: `cmake -P InstallTest.cmake` with
#   STEP=install     installs BUILD_DIR into OUT/prefix;
#   STEP=downstream  configures, builds and runs Examples/Downstream against it
#                    (the program checks a shadow on its own image);
# SOURCE_DIR, BUILD_DIR, OUT and GENERATOR (this build's) are set by
# Testing/CMakeLists.txt.
include("${CMAKE_CURRENT_LIST_DIR}/../RunOrFail.cmake")

if (STEP STREQUAL "install")
  file(REMOVE_RECURSE "${OUT}/prefix")
  run_or_fail("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${OUT}/prefix")
elseif (STEP STREQUAL "downstream")
  file(REMOVE_RECURSE "${OUT}/downstream")
  run_or_fail("configure" "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Examples/Downstream"
    -B "${OUT}/downstream" -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${OUT}/prefix")
  run_or_fail("build" "${CMAKE_COMMAND}" --build "${OUT}/downstream")
  run_or_fail("run" "${OUT}/downstream/ToonShadows" "${OUT}/toon.png")
else ()
  message(FATAL_ERROR "Unknown STEP '${STEP}'.")
endif ()
