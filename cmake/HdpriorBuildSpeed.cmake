# Build-speed switches (issue 33), on by default; each can be turned off to compare or to debug:
#   HDPRIOR_PCH    precompiled headers for the heavy headers every target's files share
#   HDPRIOR_UNITY  unity builds where they pay (the command's files: CLI11 compiled once, not 16 times;
#                  the engine's, the tests' and the sanitized I/O code's files)
option(HDPRIOR_PCH "Precompiled headers for the heavy common headers" ON)
option(HDPRIOR_UNITY "Unity builds for the targets where they pay (the command, the engine, the tests)" ON)

# The standard headers most files include; every precompiled header starts with them.
set(HDPRIOR_PCH_STD <algorithm> <array> <cmath> <cstdint> <cstdio> <filesystem> <functional> <limits>
    <memory> <optional> <span> <string> <vector>)

# hdprior_precompile(target header...): the target's .cpp files are compiled with the headers named
# already parsed (one .gch per target). No-op with HDPRIOR_PCH off.
function(hdprior_precompile target)
  if(HDPRIOR_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

# hdprior_unity(target batch_size): the target's .cpp files are compiled batch_size at a time, each
# batch as one translation unit (headers parsed and templates instantiated once per batch, not per
# file). No-op with HDPRIOR_UNITY off.
function(hdprior_unity target batch_size)
  if(HDPRIOR_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${batch_size})
  endif()
endfunction()

# PCL by the components used, without VTK and Qt: PCL's registration pulls in its `2d` and
# `features` parts, whose optional VTK support would put VTK's 38 libraries and Qt5 on every compile
# and link line. Nothing here uses PCL's visualisation, so VTK is not looked for at all.
# hdprior_find_pcl(component...) sets PCL_INCLUDE_DIRS and PCL_LIBRARIES.
macro(hdprior_find_pcl)
  set(CMAKE_DISABLE_FIND_PACKAGE_VTK ON)
  find_package(PCL 1.13 QUIET REQUIRED COMPONENTS ${ARGN})
  unset(CMAKE_DISABLE_FIND_PACKAGE_VTK)
  foreach(item ${PCL_INCLUDE_DIRS} ${PCL_LIBRARIES})
    if(item MATCHES "[Vv][Tt][Kk]|[Qq]t5")
      message(FATAL_ERROR "PCL brought ${item} onto the compile or link line")
    endif()
  endforeach()
endmacro()
