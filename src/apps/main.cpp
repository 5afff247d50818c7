// grainlab command line (placeholder until the dynamics layer lands).
#include <cstdio>
int main() { std::puts("grainlab"); return 0; }
