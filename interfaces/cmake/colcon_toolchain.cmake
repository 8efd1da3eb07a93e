# The toolchain file of `colcon build` in this environment: `source .venv/bin/activate` sets
# CMAKE_TOOLCHAIN_FILE to it (CMake reads that variable from the environment), so a package
# made by `ros2 pkg create --build-type ament_cmake` builds here with its CMakeLists.txt as the
# tutorials write it. What a ROS 2 installation would not need:
# - the wheels' exported targets are repaired (wheel_targets.cmake), and rosidl's type-support
#   libraries compile as one unit each (unity_build.cmake): CMAKE_PROJECT_INCLUDE;
# - the linters that `ros2 pkg create`'s CMakeLists.txt finds when BUILD_TESTING is on
#   (ament_lint_auto) are not on PyPI: BUILD_TESTING is off unless -DBUILD_TESTING=ON is given;
# - rosidl's generators run with this environment's Python.
set(CMAKE_PROJECT_INCLUDE "${CMAKE_CURRENT_LIST_DIR}/colcon_project.cmake")
set(BUILD_TESTING OFF CACHE BOOL "Build the tests (the ament linters are not installed here)")
if(DEFINED ENV{VIRTUAL_ENV} AND NOT Python3_EXECUTABLE)
  set(Python3_EXECUTABLE "$ENV{VIRTUAL_ENV}/bin/python3")
endif()
