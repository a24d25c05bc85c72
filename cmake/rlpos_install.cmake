# What `cmake --install` puts where, and the Debian package made of it (scripts/package).
#   bin/                              rlpos-sim, rlpos-worker, rlpos-coordinator, rlpos-campaign
#   lib/rlpos/                        their libraries and the RL module rlpos-sim loads
#   lib/python3/dist-packages/rlpos/  the Python package (Debian's python3 finds it there)
#   share/rlpos/                      campaigns/ (scenarios too), policies/, plot_campaign.py,
#                                     slurm/rlpos-workers.sbatch
#   share/man/man1/                   a page per program, from its own --help (help2man)
# The run paths (CMAKE_INSTALL_RPATH, set before the targets) lead from bin/ and lib/rlpos/ to
# lib/rlpos/, so the prefix can be anywhere. An installed rlpos-sim finds the shipped scenarios
# and policies by name (common/process/shipped_data.h).
set(RLPOS_PROGRAMS rlpos-sim rlpos-worker rlpos-coordinator rlpos-campaign)
install(TARGETS ${RLPOS_PROGRAMS} RUNTIME DESTINATION bin)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/campaigns ${PROJECT_SOURCE_DIR}/policies
        DESTINATION share/rlpos)
install(FILES ${CMAKE_BINARY_DIR}/share/rlpos/plot_campaign.py DESTINATION share/rlpos)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/slurm/rlpos-workers.sbatch DESTINATION share/rlpos/slurm)

# The build has the same share/rlpos, its data linked to the checkout: names resolve there too.
foreach(data campaigns policies)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${data} ${CMAKE_BINARY_DIR}/share/rlpos/${data} SYMBOLIC)
endforeach()

# Man pages from each program's --help and --version, with a one-line NAME each.
set(RLPOS_MAN_NAME_rlpos-sim "validate, evaluate, train and position UAVs in ns-3 scenarios")
set(RLPOS_MAN_NAME_rlpos-worker "run campaign jobs for an rlpos-coordinator over DDS")
set(RLPOS_MAN_NAME_rlpos-coordinator "schedule campaign jobs on workers over DDS and record their results")
set(RLPOS_MAN_NAME_rlpos-campaign "run, submit, follow and report RLpos experiment campaigns")
find_program(RLPOS_HELP2MAN help2man)
if(RLPOS_HELP2MAN)
  set(pages)
  foreach(program ${RLPOS_PROGRAMS})
    set(page ${CMAKE_BINARY_DIR}/man/${program}.1)
    add_custom_command(
      OUTPUT ${page}
      COMMAND ${RLPOS_HELP2MAN} --no-info --no-discard-stderr --section=1
              "--name=${RLPOS_MAN_NAME_${program}}" --output=${page} $<TARGET_FILE:${program}>
      DEPENDS ${program}
      COMMENT "Man page of ${program}")
    list(APPEND pages ${page})
  endforeach()
  add_custom_target(rlpos_man ALL DEPENDS ${pages})
  install(FILES ${pages} DESTINATION share/man/man1 OPTIONAL)  # built by rlpos_man (all)
else()
  message(STATUS "help2man not found: no man pages (apt-get install help2man)")
endif()

# The Debian package: `cpack -G DEB` in the build folder (scripts/package). Depends come from
# the libraries the programs link (dpkg-shlibdeps) and the Python modules the package imports.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME rlpos)
# The version is the build's (the release and its commit), written at build time by
# cmake/write_build_info.cmake, read when cpack runs.
set(CPACK_PROJECT_CONFIG_FILE ${RLPOS_BUILD_INFO_DIR}/rlpos_package_version.cmake)
set(CPACK_PACKAGE_CONTACT "RLpos developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Obstacle-aware UAV positioning on ns-3: RL, positioners and campaigns over DDS")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The Python module is built for one minor version of Python (Debian 12's: 3.11).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy, python3-matplotlib")
if(TARGET _rlpos)
  set(python ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR})
  math(EXPR next_minor "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= ${python}), python3 (<< ${Python_VERSION_MAJOR}.${next_minor}), python3-numpy, python3-matplotlib")
endif()
# Python writes __pycache__ into the package's folder when root imports it: removed with it.
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/cmake/debian/prerm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
