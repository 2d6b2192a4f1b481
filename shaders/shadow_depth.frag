// The shadow pass's fragment stage: nothing to write but the depth, which GL stores itself.

void main() {}
