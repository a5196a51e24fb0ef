// PLACEHOLDER until the preview lands.
#include <iostream>
int main() {
  std::cerr << "billiards-preview: not built yet\n";
  return 2;
}
