// Reads a world and prints the number of free components: proof that the installed headers and
// libraries are usable on their own.
#include <geometry/cspace.hpp>
#include <geometry/world_reader.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const polyplan::CSpace cspace(polyplan::read_world(argv[1]));
  std::cout << "free components: " << cspace.free_components().size() << '\n';
  return cspace.free_components().empty() ? 1 : 0;
}
