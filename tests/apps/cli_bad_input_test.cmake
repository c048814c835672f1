# Bad inputs of the subcommands other than detect/marker (tested beside their layers): exit 2 and
# a message naming the file, field or option.
set(DATA ${SOURCE_DIR}/tests/data)

include(${CMAKE_CURRENT_LIST_DIR}/../cli_expect.cmake)

file(WRITE ${WORK_DIR}/bad_scenario.yaml
     "robot_start: {x: 0, y: 0}\nshelves:\n  - {id: 1, model: no-such-model, pose: {x: 2, y: 0}}\n")
file(WRITE ${WORK_DIR}/unknown_key_scenario.yaml "robot_start: {x: 0, y: 0}\nshelvs: []\n")

expect_shelfdock(2 "missing_scenario.yaml" simulate --scenario ${DATA}/missing_scenario.yaml
           --pose 0,0,0 --out ${WORK_DIR}/x.jsonl)
expect_shelfdock(2 "bad_scenario.yaml: shelves\\[0\\].model" simulate --scenario
           ${WORK_DIR}/bad_scenario.yaml --pose 0,0,0 --out ${WORK_DIR}/x.jsonl)
expect_shelfdock(2 "unknown_key_scenario.yaml: shelvs" simulate --scenario
           ${WORK_DIR}/unknown_key_scenario.yaml --pose 0,0,0 --out ${WORK_DIR}/x.jsonl)
expect_shelfdock(2 "--pose" simulate --scenario ${SOURCE_DIR}/config/scenarios/paper_docking.yaml
           --pose 0,0 --out ${WORK_DIR}/x.jsonl)
expect_shelfdock(2 "bad_scenario.yaml" dock --scenario ${WORK_DIR}/bad_scenario.yaml
           --models ${SOURCE_DIR}/config/models.yaml)
expect_shelfdock(2 "method" dock --scenario ${SOURCE_DIR}/config/scenarios/paper_docking.yaml
           --models ${SOURCE_DIR}/config/models.yaml --method teleport)
expect_shelfdock(2 "missing.bag" bag --bag ${DATA}/missing.bag)
expect_shelfdock(2 "example_scan.json" eval-real --bag ${DATA}/example_scan.json
           --models ${SOURCE_DIR}/config/models.yaml)
