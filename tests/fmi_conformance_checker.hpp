#pragma once
// Checks a modelDescription.xml against the rules of the FMI 3.0.2 standard's text that the schema cannot
// express, and the few PeriStep adds (fmi_conformance_checker.cpp lists them with their sections).
#include <libxml/tree.h>

#include <string>
#include <vector>

// One line per broken rule: "rule (section): what"; empty when the description conforms.
std::vector<std::string> conformanceViolations(xmlNodePtr root);
