# cmake -P: gq-fit on a box of half extents (1, 0.5, 0.25) written as an OBJ: the fit is the box itself, within the
# tolerance, written as one OBJ part (its 8 corners) and a JSON report naming it with its exact half extents and
# every representation tried; a tolerance <= 0 and an unknown representation are refused with a message and write
# nothing.
file(MAKE_DIRECTORY ${WORK})
set(mesh ${WORK}/box.obj)
file(WRITE ${mesh} "v -1 -0.5 -0.25\nv 1 -0.5 -0.25\nv -1 0.5 -0.25\nv 1 0.5 -0.25\n"
                   "v -1 -0.5 0.25\nv 1 -0.5 0.25\nv -1 0.5 0.25\nv 1 0.5 0.25\n"
                   "f 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\n"
                   "f 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n")
file(REMOVE ${WORK}/box-fit.json ${WORK}/box-fit_part0.obj)

execute_process(COMMAND ${GQ_FIT} ${mesh} --tolerance 0.001 --contain --out ${WORK}/box-fit
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gq-fit failed (${rc}): ${err}")
endif()
file(READ ${WORK}/box-fit.json report)
string(JSON representation GET "${report}" representation)
string(JSON within GET "${report}" withinTolerance)
string(JSON bound GET "${report}" errorBound)
string(JSON parts LENGTH "${report}" parts)
string(JSON type GET "${report}" parts 0 type)
string(JSON hx GET "${report}" parts 0 halfExtents 0)
string(JSON hy GET "${report}" parts 0 halfExtents 1)
string(JSON hz GET "${report}" parts 0 halfExtents 2)
string(JSON tried LENGTH "${report}" candidates)
if(NOT representation STREQUAL "box" OR NOT within STREQUAL "ON" OR NOT parts EQUAL 1 OR NOT type STREQUAL "box")
  message(FATAL_ERROR "gq-fit: expected one box within the tolerance, got ${representation} (${parts} parts, within ${within})")
endif()
if(bound GREATER 0.001 OR tried LESS 3)
  message(FATAL_ERROR "gq-fit: bound ${bound} above the tolerance, or ${tried} representations tried (sphere, capsule, box)")
endif()
# if() compares numbers as doubles.
foreach(half "${hx};0.999999999;1.000000001" "${hy};0.499999999;0.500000001" "${hz};0.249999999;0.250000001")
  list(GET half 0 got)
  list(GET half 1 low)
  list(GET half 2 high)
  if(got LESS low OR got GREATER high)
    message(FATAL_ERROR "gq-fit: box half extent ${got}, expected within [${low}, ${high}]")
  endif()
endforeach()
file(STRINGS ${WORK}/box-fit_part0.obj corners REGEX "^v ")
list(LENGTH corners corners)
if(NOT corners EQUAL 8)
  message(FATAL_ERROR "gq-fit: the box part's OBJ has ${corners} vertices, expected 8")
endif()

file(REMOVE ${WORK}/bad.json)
execute_process(COMMAND ${GQ_FIT} ${mesh} --tolerance 0 --out ${WORK}/bad ERROR_VARIABLE err RESULT_VARIABLE rc)
if(rc EQUAL 0 OR NOT err MATCHES "tolerance" OR EXISTS ${WORK}/bad.json)
  message(FATAL_ERROR "gq-fit accepted a tolerance of 0 (${rc}): ${err}")
endif()
execute_process(COMMAND ${GQ_FIT} ${mesh} --tolerance 0.1 --allow box,ellipsoid --out ${WORK}/bad
                ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 2 OR NOT err MATCHES "unknown representation 'ellipsoid'" OR EXISTS ${WORK}/bad.json)
  message(FATAL_ERROR "gq-fit accepted an unknown representation (${rc}): ${err}")
endif()
