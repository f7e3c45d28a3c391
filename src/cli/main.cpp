// The casteljau command-line tool: a thin shell over the library (see README.md).
#include <cstdio>
int main() { std::puts("casteljau: under construction"); return 0; }
