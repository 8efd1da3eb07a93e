# Repairs the ROS 2 Jazzy wheels' exported CMake targets, at the end of the package's top
# CMakeLists.txt (a deferred call), so a package's CMakeLists.txt stays as in a ROS 2 workspace.
#
# The wheels on PyPI export targets whose include directories name the wheel build host's
# Python and NumPy headers (/opt/python/cpXY-cpXY/include/...), which do not exist on this
# machine, so CMake's generate step fails. Whatever packages the CMakeLists.txt and rosidl
# found by then, their imported targets are pointed at this interpreter's include directories.
# Include directories are read at generate time, which comes after this call.
cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL _ros_tutorials_fix_wheel_targets)

function(_ros_tutorials_fix_wheel_targets)
  get_directory_property(_imported_targets DIRECTORY "${CMAKE_SOURCE_DIR}" IMPORTED_TARGETS)
  set(_broken)
  foreach(_target IN LISTS _imported_targets)
    get_target_property(_dirs ${_target} INTERFACE_INCLUDE_DIRECTORIES)
    if(_dirs AND "${_dirs}" MATCHES "/opt/python/")
      list(APPEND _broken ${_target})
    endif()
  endforeach()
  if(NOT _broken)
    return()
  endif()
  find_package(Python3 REQUIRED COMPONENTS Interpreter Development NumPy)
  foreach(_target IN LISTS _broken)
    get_target_property(_dirs ${_target} INTERFACE_INCLUDE_DIRECTORIES)
    list(TRANSFORM _dirs REPLACE "^/opt/python/[^;]*/include/python[0-9.]+$" "${Python3_INCLUDE_DIRS}")
    list(TRANSFORM _dirs REPLACE "^/opt/python/[^;]*/numpy/[^;]*include$" "${Python3_NumPy_INCLUDE_DIRS}")
    set_target_properties(${_target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_dirs}")
  endforeach()
endfunction()
