# Fails unless DOC (docs/mcdtool.md) equals what `MCDTOOL --help-markdown`
# prints. Regenerate with: build/bin/mcdtool --help-markdown > docs/mcdtool.md
execute_process(COMMAND ${MCDTOOL} --help-markdown OUTPUT_VARIABLE generated RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "mcdtool --help-markdown failed (${status})")
endif()
if(NOT EXISTS ${DOC})
  message(FATAL_ERROR "${DOC} is missing; run: mcdtool --help-markdown > docs/mcdtool.md")
endif()
file(READ ${DOC} committed)
if(NOT generated STREQUAL committed)
  message(FATAL_ERROR "${DOC} is out of date; run: mcdtool --help-markdown > docs/mcdtool.md")
endif()
