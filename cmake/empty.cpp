// Keeps a module library valid while its folder is still empty.
