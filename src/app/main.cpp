#include "app/Application.hpp"

int main(int argc, char** argv) { return peridot::runApplication(argc, argv); }
