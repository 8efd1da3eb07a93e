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
  _ros_tutorials_interface_ranks()
  foreach(_target IN LISTS _targets)
    if(_target MATCHES "${_pattern}")
      _ros_tutorials_order_sources(${_target})
      set_target_properties(${_target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
    endif()
  endforeach()
endfunction()

# In one unit, an interface's type support must come before that of an interface of the same
# package using it (example_interfaces: MultiArrayLayout before Float32MultiArray), or C++
# sees a template specialized after its instantiation. Each interface gets a rank: 0 if it
# uses no other interface of its package, else one more than the highest rank it uses.
function(_ros_tutorials_interface_ranks)
  file(GLOB _files "${CMAKE_SOURCE_DIR}/msg/*.msg" "${CMAKE_SOURCE_DIR}/srv/*.srv"
    "${CMAKE_SOURCE_DIR}/action/*.action")
  set(_names)
  foreach(_file IN LISTS _files)
    get_filename_component(_name "${_file}" NAME_WE)
    list(APPEND _names ${_name})
    file(STRINGS "${_file}" _lines)
    set(_uses_${_name})
    foreach(_line IN LISTS _lines)
      if(_line MATCHES "^[ \t]*(${PROJECT_NAME}/)?([A-Z][A-Za-z0-9]*)[\[ \t<]")
        list(APPEND _uses_${_name} ${CMAKE_MATCH_2})
      endif()
    endforeach()
    set(_rank_${_name} 0)
  endforeach()
  list(LENGTH _names _count)
  foreach(_round RANGE ${_count})
    foreach(_name IN LISTS _names)
      foreach(_used IN LISTS _uses_${_name})
        if(DEFINED _rank_${_used} AND NOT _rank_${_name} GREATER _rank_${_used})
          math(EXPR _rank_${_name} "${_rank_${_used}} + 1")
        endif()
      endforeach()
    endforeach()
  endforeach()
  foreach(_name IN LISTS _names)
    # The generated files are named in snake case: MultiArrayLayout -> multi_array_layout.
    string(REGEX REPLACE "([a-z0-9])([A-Z])" "\\1_\\2" _snake "${_name}")
    string(REGEX REPLACE "([A-Z])([A-Z][a-z])" "\\1_\\2" _snake "${_snake}")
    string(TOLOWER "${_snake}" _snake)
    set(_ros_tutorials_rank_${_snake} ${_rank_${_name}} PARENT_SCOPE)
  endforeach()
endfunction()

function(_ros_tutorials_order_sources target)
  get_target_property(_sources ${target} SOURCES)
  set(_ranked)
  foreach(_source IN LISTS _sources)
    get_filename_component(_file "${_source}" NAME)
    set(_rank 0)
    if(_file MATCHES "^([a-z0-9_]+)__" AND DEFINED _ros_tutorials_rank_${CMAKE_MATCH_1})
      set(_rank ${_ros_tutorials_rank_${CMAKE_MATCH_1}})
    endif()
    list(APPEND _ranked_${_rank} "${_source}")
    list(APPEND _ranked ${_rank})
  endforeach()
  list(REMOVE_DUPLICATES _ranked)
  list(SORT _ranked COMPARE NATURAL)
  set(_ordered)
  foreach(_rank IN LISTS _ranked)
    list(APPEND _ordered ${_ranked_${_rank}})
  endforeach()
  set_property(TARGET ${target} PROPERTY SOURCES ${_ordered})
endfunction()
