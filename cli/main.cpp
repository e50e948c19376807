#include <cstdio>
int main() { std::puts("radmesh: skeleton"); return 0; }
