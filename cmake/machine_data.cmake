# zcube_machine_data(SOURCE_DIR OUT_CPP): writes OUT_CPP from cmake/machine_data.cpp.in with the text
# of every machines/*.json and machines/cpu/*.json under SOURCE_DIR, so the binary carries its data
# (relocatable). Adding, removing or editing a data file re-runs CMake.

# A C++ initializer {"path", R"zcjson(text)zcjson"} per file, relative to root, in out_var.
function(zcube_embed_json out_var root) # files: ARGN
  set(entries "")
  foreach(f ${ARGN})
    file(RELATIVE_PATH rel ${root} ${f})
    file(READ ${f} text)
    string(FIND "${text}" ")zcjson\"" clash)
    if(NOT clash EQUAL -1)
      message(FATAL_ERROR "${rel}: holds )zcjson\", which ends the C++ string it is compiled into")
    endif()
    string(APPEND entries "    {\"${rel}\", R\"zcjson(${text})zcjson\"},\n")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${f})
  endforeach()
  set(${out_var} "${entries}" PARENT_SCOPE)
endfunction()

function(zcube_machine_data root out_cpp)
  file(GLOB machines CONFIGURE_DEPENDS ${root}/machines/*.json)
  file(GLOB cpus CONFIGURE_DEPENDS ${root}/machines/cpu/*.json)
  list(SORT machines)
  list(SORT cpus)
  set(operations ${root}/machines/cpu/operations.json)
  list(REMOVE_ITEM cpus ${operations})
  if(NOT machines OR NOT cpus)
    message(FATAL_ERROR "machines/: no machine (*.json) or no CPU (cpu/*.json) to build in")
  endif()
  zcube_embed_json(ZC_MACHINE_FILES ${root} ${machines})
  zcube_embed_json(ZC_CPU_FILES ${root} ${cpus})
  file(READ ${operations} ZC_CPU_OPERATIONS)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${operations})
  configure_file(${root}/cmake/machine_data.cpp.in ${out_cpp} @ONLY)
endfunction()
