# Writes the list of a worker's student files by content (grader/engine/worker_sources.h):
# one line "<SHA-256> <folder>/<file>" per .cpp under ROOT, into OUT.
# cmake -D ROOT=<assignments or solutions folder> -D OUT=<worker>.sources -P worker_sources.cmake
file(GLOB_RECURSE files RELATIVE ${ROOT} ${ROOT}/*.cpp)
list(SORT files)
set(text "")
foreach(file IN LISTS files)
  file(SHA256 ${ROOT}/${file} digest)
  string(APPEND text "${digest} ${file}\n")
endforeach()
file(WRITE ${OUT}.new "${text}")
file(RENAME ${OUT}.new ${OUT})
