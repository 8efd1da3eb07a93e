# Included after the project() of every package `colcon build` configures in this environment
# (colcon_toolchain.cmake sets CMAKE_PROJECT_INCLUDE to it).
include("${CMAKE_CURRENT_LIST_DIR}/wheel_targets.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/unity_build.cmake")
