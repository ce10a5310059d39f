#include "cli/commands.h"

int main(int argc, char** argv) { return taa::cli::dispatch(argc, argv); }
