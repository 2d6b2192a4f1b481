// Placeholder until the asset generator lands (issue 2); replaced in this session.
#include <cstdio>
int main() {
  std::fprintf(stderr, "twinraster-assets: not built yet\n");
  return 2;
}
