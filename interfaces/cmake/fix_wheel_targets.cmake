# The ROS 2 Jazzy wheels on PyPI export CMake targets whose include directories
# name the wheel build host's Python headers (/opt/python/cpXY-cpXY/include/...),
# and NumPy headers, which do not exist on this machine, so CMake's generate step fails.
# Find every interface package rosidl will pull in, then point those paths at
# this interpreter's real include directories. A normal ROS 2 workspace skips this.
find_package(Python3 REQUIRED COMPONENTS Interpreter Development NumPy)
foreach(_pkg builtin_interfaces service_msgs action_msgs unique_identifier_msgs)
  find_package(${_pkg} REQUIRED)
endforeach()

get_directory_property(_imported_targets IMPORTED_TARGETS)
foreach(_target IN LISTS _imported_targets)
  get_target_property(_dirs ${_target} INTERFACE_INCLUDE_DIRECTORIES)
  if(_dirs AND "${_dirs}" MATCHES "/opt/python/")
    list(TRANSFORM _dirs REPLACE "^/opt/python/[^;]*/include/python[0-9.]+$" "${Python3_INCLUDE_DIRS}")
    list(TRANSFORM _dirs REPLACE "^/opt/python/[^;]*/numpy/[^;]*include$" "${Python3_NumPy_INCLUDE_DIRS}")
    set_target_properties(${_target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_dirs}")
  endif()
endforeach()
