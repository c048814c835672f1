# Bad inputs of the subcommands other than detect/marker (tested beside their layers): exit 2 and
# a message naming the file, field or option.
set(DATA ${SOURCE_DIR}/tests/data)

function(expect_run expected_code must_match)
  execute_process(COMMAND ${SHELFDOCK} ${ARGN}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expected_code)
    message(FATAL_ERROR "${ARGN}: exit ${code}, expected ${expected_code}\n${out}\n${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${must_match}")
    message(FATAL_ERROR "${ARGN}: output does not match '${must_match}'\n${out}\n${err}")
  endif()
endfunction()

file(WRITE ${WORK_DIR}/bad_scenario.yaml
     "robot_start: {x: 0, y: 0}\nshelves:\n  - {id: 1, model: no-such-model, pose: {x: 2, y: 0}}\n")
file(WRITE ${WORK_DIR}/unknown_key_scenario.yaml "robot_start: {x: 0, y: 0}\nshelvs: []\n")

expect_run(2 "missing_scenario.yaml" simulate --scenario ${DATA}/missing_scenario.yaml
           --pose 0,0,0 --out ${WORK_DIR}/x.jsonl)
expect_run(2 "bad_scenario.yaml: shelves\\[0\\].model" simulate --scenario
           ${WORK_DIR}/bad_scenario.yaml --pose 0,0,0 --out ${WORK_DIR}/x.jsonl)
expect_run(2 "unknown_key_scenario.yaml: shelvs" simulate --scenario
           ${WORK_DIR}/unknown_key_scenario.yaml --pose 0,0,0 --out ${WORK_DIR}/x.jsonl)
expect_run(2 "--pose" simulate --scenario ${SOURCE_DIR}/config/scenarios/paper_docking.yaml
           --pose 0,0 --out ${WORK_DIR}/x.jsonl)
expect_run(2 "bad_scenario.yaml" dock --scenario ${WORK_DIR}/bad_scenario.yaml
           --models ${SOURCE_DIR}/config/models.yaml)
expect_run(2 "method" dock --scenario ${SOURCE_DIR}/config/scenarios/paper_docking.yaml
           --models ${SOURCE_DIR}/config/models.yaml --method teleport)
expect_run(2 "missing.bag" bag --bag ${DATA}/missing.bag)
expect_run(2 "example_scan.json" eval-real --bag ${DATA}/example_scan.json
           --models ${SOURCE_DIR}/config/models.yaml)
