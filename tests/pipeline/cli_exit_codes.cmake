# Exit codes and error lines of the grainflow command line.
#   cmake -DGRAINFLOW=<exe> -DSRC=<source dir> -DWORK=<scratch dir> -P cli_exit_codes.cmake
# 0 success, 1 a run failed, 2 usage/configuration error with one line on stderr.
set(failures 0)
set(data ${SRC}/tests/pipeline/data)
set(corpus ${SRC}/tests/pipeline/corpus)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# expect(<code> <stderr regex or "">  <args...>)
function(expect code err_regex)
  execute_process(COMMAND ${GRAINFLOW} ${ARGN} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL code)
    message(SEND_ERROR "grainflow ${ARGN}: exit ${rc}, expected ${code}\nstdout: ${out}\nstderr: ${err}")
  elseif(err_regex AND NOT err MATCHES "${err_regex}")
    message(SEND_ERROR "grainflow ${ARGN}: stderr does not match '${err_regex}':\n${err}")
  else()
    message(STATUS "ok: exit ${rc}: grainflow ${ARGN}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

# usage errors -> 2, one line
expect(2 "" )
expect(2 "^grainflow: unknown command 'frobnicate'" frobnicate)
expect(2 "^grainflow run: missing SCENE.yaml" run)
expect(2 "^grainflow campaign: --jobs: expected an integer" campaign ${data}/bc_campaign.yaml --jobs 0)
expect(2 "^grainflow campaign: unknown option '--frob'" campaign ${data}/bc_campaign.yaml --frob)
expect(2 "^grainflow post: .*not a directory" post ${WORK}/nonexistent)
# configuration errors -> 2, exactly "file:line:column: message\n"
expect(2 "^[^\n]*/unknown_key.yaml:3:3: unknown key 'frictoin' in contact \\(did you mean 'friction'\\?\\)\n$"
       run ${corpus}/unknown_key.yaml)
expect(2 "^[^\n]*/tab_indent.yaml:3:1: tab character[^\n]*\n$" campaign ${corpus}/tab_indent.yaml -o ${WORK}/runs)
expect(2 "^[^\n]*/binary_junk.yaml:1:1: not a text file[^\n]*\n$" check ${corpus}/binary_junk.yaml)
expect(2 "^/nonexistent/x.yaml:1:1: cannot open: No such file or directory\n$" check /nonexistent/x.yaml)
expect(2 "^--set fluid.modle=none: unknown key 'modle' in fluid \\(did you mean 'model'\\?\\)\n$"
       check ${data}/bc_ok.yaml --set fluid.modle=none)
if(EXISTS ${WORK}/runs)
  message(SEND_ERROR "a configuration error started something: ${WORK}/runs exists")
endif()
# help and version -> 0
foreach(cmd run campaign check demo post bench)
  expect(0 "" ${cmd} --help)
endforeach()
expect(0 "" --version)
if(NOT last_out MATCHES "^grainflow [0-9]+\\.[0-9]+\\.[0-9]+ \\(([0-9a-z]+(-dirty\\.[0-9a-f]+)?)\\)")
  message(SEND_ERROR "--version printed '${last_out}'")
endif()
# the revision is the source tree's at build time, not at configure time: in a
# git checkout it is HEAD's short hash ("-dirty.<diff hash>" with uncommitted edits to
# tracked files), whatever commit the build directory was configured at
set(printed_rev "${CMAKE_MATCH_1}")
execute_process(COMMAND git rev-parse --short=7 HEAD WORKING_DIRECTORY ${SRC}
                OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE git_rc)
if(git_rc EQUAL 0 AND NOT head STREQUAL "")
  string(REGEX REPLACE "-dirty\\.[0-9a-f]+$" "" printed_hash "${printed_rev}")
  if(NOT printed_hash STREQUAL head)
    message(SEND_ERROR "--version names revision '${printed_rev}', the source tree is at ${head}")
  else()
    message(STATUS "ok: --version names the source tree's revision ${printed_rev}")
  endif()
endif()
# every example configuration expands against the current scene tables
file(GLOB configs ${SRC}/configs/*.yaml)
foreach(cfg ${configs})
  expect(0 "" check ${cfg} --brief)
endforeach()
# the embedded demo is configs/demo.yaml, byte for byte
expect(0 "" demo --print)
file(READ ${SRC}/configs/demo.yaml demo_text)
if(NOT last_out STREQUAL demo_text)
  message(SEND_ERROR "grainflow demo --print differs from configs/demo.yaml")
endif()
# runs: 0 done, 1 failed
expect(0 "" run ${data}/bc_ok.yaml -o ${WORK}/runs)
expect(1 "failed: physically impossible input" run ${data}/bc_fail.yaml -o ${WORK}/runs)
file(GLOB st ${WORK}/runs/cli_fail/*/status)
file(READ "${st}" st_text)
if(NOT st_text MATCHES "^failed: physically impossible input")
  message(SEND_ERROR "status of the failed run: '${st_text}'")
endif()
# a campaign with one failing run: the others are done, exit 1; resume skips them
expect(1 "" campaign ${data}/bc_campaign.yaml -o ${WORK}/runs --jobs 2 --no-post)
if(NOT last_out MATCHES "2 done, 1 failed, 0 skipped")
  message(SEND_ERROR "campaign counts: ${last_out}")
endif()
expect(1 "" campaign ${data}/bc_campaign.yaml -o ${WORK}/runs --resume --no-post)
if(NOT last_out MATCHES "0 done, 1 failed, 2 skipped")
  message(SEND_ERROR "resume counts: ${last_out}")
endif()
expect(0 "" campaign ${data}/bc_campaign.yaml -o ${WORK}/runs --index 1 --no-post)
expect(2 "--index 7: campaign cli_campaign has runs 0..2" campaign ${data}/bc_campaign.yaml --index 7)
# Slurm array: one task per run
expect(0 "" campaign ${data}/bc_campaign.yaml -o ${WORK}/runs --emit slurm)
file(READ ${WORK}/runs/cli_campaign/cli_campaign.slurm slurm)
if(NOT slurm MATCHES "#SBATCH --array=0-2" OR NOT slurm MATCHES "--index \"\\$SLURM_ARRAY_TASK_ID\" --resume")
  message(SEND_ERROR "slurm script:\n${slurm}")
endif()
