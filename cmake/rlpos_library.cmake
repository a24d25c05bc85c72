# rlpos_library(NAME [STATIC|SHARED|MODULE] SOURCES ... [DEPENDS ...] [PRIVATE ...])
# One folder, one library: NAME is built from the .cc files of the calling folder. Without a type
# it is shared, or static with -DRLPOS_SHARED_LIBS=OFF (the top CMakeLists.txt says why). DEPENDS are
# public (their headers appear in ours), PRIVATE are used only inside. Every include names its
# top folder ("common/store/..."), so the one include root is the repository's.
function(rlpos_library name)
  cmake_parse_arguments(arg "STATIC;SHARED;MODULE" "" "SOURCES;DEPENDS;PRIVATE" ${ARGN})
  if(RLPOS_SHARED_LIBS)
    set(type SHARED)
  else()
    set(type STATIC)
  endif()
  if(arg_STATIC)
    set(type STATIC)
  elseif(arg_SHARED)
    set(type SHARED)
  elseif(arg_MODULE)
    set(type MODULE)
  endif()
  add_library(${name} ${type} ${arg_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${arg_DEPENDS} PRIVATE ${arg_PRIVATE} rlpos_warnings)
endfunction()

# rlpos_program(NAME SOURCES ... [DEPENDS ...]): a program of the calling folder, in bin/.
function(rlpos_program name)
  cmake_parse_arguments(arg "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${arg_SOURCES})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${arg_DEPENDS} rlpos_warnings)
endfunction()
