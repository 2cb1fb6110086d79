# Fails when Doxygen wrote any warning to WARNINGS (cmake -DWARNINGS=FILE -P check_doc_warnings.cmake).
file(READ "${WARNINGS}" text)
string(STRIP "${text}" text)
if(NOT text STREQUAL "")
  message(FATAL_ERROR "Doxygen warnings:\n${text}")
endif()
