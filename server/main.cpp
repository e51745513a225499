// Placeholder until the HTTP layer lands.
int main() { return 0; }
