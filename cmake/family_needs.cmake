# The optional families each optional family's library links (polyplan/FAMILY/CMakeLists.txt):
# cmake/families.cmake builds them with it, and tests/layout/families_left_out.cmake accepts a
# guard of the family for the headers of what it needs.
set(needs_incremental grids)
set(needs_arm sampling)
set(needs_car sampling)
