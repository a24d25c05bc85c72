# cmake -DLIBRARIES=a|b|c -DFORBIDDEN=x|y -P forbidden_libraries.cmake: fails naming the first
# of FORBIDDEN that LIBRARIES (a target's link closure) holds.
cmake_minimum_required(VERSION 3.18)
string(REPLACE "|" ";" libraries "${LIBRARIES}")
string(REPLACE "|" ";" forbidden "${FORBIDDEN}")
if(NOT libraries)
  message(FATAL_ERROR "no libraries given: the closure is empty")
endif()
foreach(lib ${forbidden})
  if(lib IN_LIST libraries)
    message(FATAL_ERROR "links ${lib}: ${LIBRARIES}")
  endif()
endforeach()
message(STATUS "links none of ${FORBIDDEN}")
