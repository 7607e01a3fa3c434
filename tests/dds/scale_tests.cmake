# Scale tests (issue 12): a subscriber that stops reading, and a short fleet.
# 240 s each; a sanitizer build (scripts/sanitize.sh) runs the services up to
# ten times slower and multiplies it by SCANFILTER_TEST_TIMEOUT_FACTOR.
set(SCANFILTER_TEST_TIMEOUT_FACTOR 1 CACHE STRING "Multiplies the scale tests' ctest timeout (sanitizer builds)")
math(EXPR SCANFILTER_SCALE_TEST_TIMEOUT "240 * ${SCANFILTER_TEST_TIMEOUT_FACTOR}")
add_executable(stalled_subscriber ${CMAKE_CURRENT_LIST_DIR}/stalled_subscriber.cpp)
target_compile_options(stalled_subscriber PRIVATE ${SCANFILTER_WARNINGS})
target_link_libraries(stalled_subscriber PRIVATE scanfilter_dds)

add_test(NAME dds_slow_subscriber
         COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/slow_subscriber_test.sh ${CMAKE_BINARY_DIR} ${PROJECT_SOURCE_DIR})
set_tests_properties(dds_slow_subscriber PROPERTIES TIMEOUT ${SCANFILTER_SCALE_TEST_TIMEOUT} RUN_SERIAL TRUE)
# Two robots for 10 s: every scan arrives, each robot's labels are its own.
add_test(NAME dds_fleet_short
         COMMAND env BUILD_DIR=${CMAKE_BINARY_DIR} bash ${PROJECT_SOURCE_DIR}/bench/run-fleet-bench.sh --robots 2 --seconds 10)
set_tests_properties(dds_fleet_short PROPERTIES TIMEOUT ${SCANFILTER_SCALE_TEST_TIMEOUT} RUN_SERIAL TRUE)
