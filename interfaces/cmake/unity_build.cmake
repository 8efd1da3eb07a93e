# Compiles each of rosidl's C++ type-support libraries (and the Python extension) as one
# translation unit per library instead of one per interface: the same generated sources,
# #included one after another by a file CMake writes (CMake's UNITY_BUILD). Almost all the
# compile time of rosidl's generated code is parsing the same headers (Fast CDR, the C++
# standard library, Python and NumPy) again for every interface; this parses them once per
# library. The libraries export the same symbols. tools/build_interfaces.py passes this file
# as CMAKE_PROJECT_INCLUDE, so the packages' CMakeLists.txt stay as in a ROS 2 workspace.
#
# Not rosidl_generator_c's library: its generated *__description.c files each define the same
# file-level static names (toplevel_type_raw_source, ...), so they cannot share one unit.
cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL _ros_tutorials_unity_build)

function(_ros_tutorials_unity_build)
  get_directory_property(_targets DIRECTORY "${CMAKE_SOURCE_DIR}" BUILDSYSTEM_TARGETS)
  get_directory_property(_subdirectories DIRECTORY "${CMAKE_SOURCE_DIR}" SUBDIRECTORIES)
  foreach(_subdirectory IN LISTS _subdirectories)
    get_directory_property(_more DIRECTORY "${_subdirectory}" BUILDSYSTEM_TARGETS)
    list(APPEND _targets ${_more})
  endforeach()
  set(_pattern "^${PROJECT_NAME}(_s)?__rosidl_(typesupport_[a-z_]+|generator_py)$")
  foreach(_target IN LISTS _targets)
    if(_target MATCHES "${_pattern}")
      set_target_properties(${_target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
    endif()
  endforeach()
endfunction()
