# rlpos_library(NAME [STATIC|SHARED|MODULE] [NOT_INSTALLED] SOURCES ... [DEPENDS ...] [PRIVATE ...])
# One folder, one library: NAME is built from the .cc files of the calling folder. Without a type
# it is shared, or static with -DRLPOS_SHARED_LIBS=OFF (the top CMakeLists.txt says why). DEPENDS are
# public (their headers appear in ours), PRIVATE are used only inside. Every include names its
# top folder ("common/store/..."), so the one include root is the repository's. A shared library
# or module is installed (cmake/rlpos_install.cmake) unless NOT_INSTALLED: one no program loads.
function(rlpos_library name)
  cmake_parse_arguments(arg "STATIC;SHARED;MODULE;NOT_INSTALLED" "" "SOURCES;DEPENDS;PRIVATE" ${ARGN})
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
  if(NOT type STREQUAL "STATIC" AND NOT arg_NOT_INSTALLED)
    install(TARGETS ${name} LIBRARY DESTINATION ${RLPOS_INSTALL_LIBDIR})
  endif()
endfunction()

# rlpos_use_tcmalloc(TARGET): the program allocates with tcmalloc (Debian's libgoogle-perftools-dev)
# instead of glibc's malloc. ns-3's Wi-Fi model allocates per frame, and a packet-level run spent
# about a fifth of its cycles in glibc's malloc and free (docs/benchmarks.md). The numbers are the
# same with either (test sim.same_numbers_with_glibc_malloc). Not with the sanitizers, which bring
# their own allocator, nor with -DRLPOS_TCMALLOC=OFF.
function(rlpos_use_tcmalloc target)
  if(NOT RLPOS_TCMALLOC OR RLPOS_SANITIZE)
    return()
  endif()
  find_library(RLPOS_TCMALLOC_LIBRARY NAMES tcmalloc_minimal)
  if(NOT RLPOS_TCMALLOC_LIBRARY)
    message(FATAL_ERROR "tcmalloc not found: apt-get install libgoogle-perftools-dev "
                        "(scripts/bootstrap does), or configure with -DRLPOS_TCMALLOC=OFF")
  endif()
  # Kept even where nothing names a tcmalloc symbol: it replaces malloc by being loaded. One
  # item, so that the linker's --as-needed state around it is put back as it was.
  target_link_libraries(${target} PRIVATE
                        "-Wl,--push-state,--no-as-needed,${RLPOS_TCMALLOC_LIBRARY},--pop-state")
endfunction()

# rlpos_program(NAME SOURCES ... [DEPENDS ...]): a program of the calling folder, in bin/.
function(rlpos_program name)
  cmake_parse_arguments(arg "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${arg_SOURCES})
  # Installed in bin/, its libraries in lib/rlpos (cmake/rlpos_install.cmake).
  set_target_properties(${name} PROPERTIES INSTALL_RPATH "$ORIGIN/../${RLPOS_INSTALL_LIBDIR}")
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${arg_DEPENDS} rlpos_warnings)
endfunction()
