# check_cli.cmake: testrender's command line rejects bad arguments with exit
# status 2 and a one-line "testrender: error:" message, and --list works.
# Usage: cmake -DTESTRENDER=<binary> -DWORK_DIR=<dir> -P check_cli.cmake
set(out "${WORK_DIR}/cli_check.exr")
set(cases
  "--scene,cornell,--spp,0,-o,${out}|--spp wants"
  "--scene,cornell,--spp,12x,-o,${out}|--spp wants"
  "--scene,cornell,--res,256,-o,${out}|--res wants"
  "--scene,cornell,--res,0x16,-o,${out}|--res wants"
  "--scene,cornell,--seed,-1,-o,${out}|--seed wants"
  "--scene,cornell,--threads,many,-o,${out}|--threads wants"
  "--scene,shot_truck,--frame,-1,-o,${out}|--frame wants"
  "--scene,shot_truck,--frame,1000000,-o,${out}|--frame wants"
  "--scene,nosuch,-o,${out}|unknown scene 'nosuch'"
  "--scene,cornell,--bogus,-o,${out}|unknown argument '--bogus'"
  "--scene,cornell|-o FILE is required"
  "-o,${out}|--scene is required"
  "--scene,cornell,-o|-o needs a value")
foreach(case IN LISTS cases)
  # a case is "arg,arg,...|expected message"
  string(FIND "${case}" "|" bar)
  string(SUBSTRING "${case}" 0 ${bar} arglist)
  math(EXPR after "${bar} + 1")
  string(SUBSTRING "${case}" ${after} -1 expected)
  string(REPLACE "," ";" args "${arglist}")
  execute_process(COMMAND ${TESTRENDER} ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE stdout
                  ERROR_VARIABLE stderr)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "testrender ${args}: exit ${rc}, expected 2\n${stderr}")
  endif()
  string(FIND "${stderr}" "testrender: error: ${expected}" found)
  if(found EQUAL -1)
    message(FATAL_ERROR "testrender ${args}: stderr lacks '${expected}':\n${stderr}")
  endif()
  if(EXISTS "${out}")
    message(FATAL_ERROR "testrender ${args}: wrote ${out} despite the error")
  endif()
endforeach()

execute_process(COMMAND ${TESTRENDER} --list RESULT_VARIABLE rc OUTPUT_VARIABLE stdout)
foreach(scene cornell mirrors textured dof interior transparent shot_static shot_truck shot_object)
  if(NOT rc EQUAL 0 OR NOT stdout MATCHES "${scene} ")
    message(FATAL_ERROR "testrender --list: exit ${rc}, no ${scene}:\n${stdout}")
  endif()
endforeach()
