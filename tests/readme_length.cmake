# The README is a product page: at most MAX_LINES lines; detail belongs in docs/.
file(READ ${README} text)
string(REGEX MATCHALL "\n" newlines "${text}")
list(LENGTH newlines lines)
if(lines GREATER MAX_LINES)
  message(FATAL_ERROR "README.md has ${lines} lines, more than ${MAX_LINES}: move detail to docs/")
endif()
message(STATUS "README.md: ${lines} lines (at most ${MAX_LINES})")
