// FMI 2.0's resource location: file URIs to the native folder the load blocks read.
#include "resource_uri.hpp"

#include <doctest/doctest.h>

using yamsc::fmi::folder_of_file_uri;

TEST_CASE("fmi2 resource URIs: the forms of file URIs, escapes, and what is refused") {
    CHECK(folder_of_file_uri("file:///tmp/unit/resources") == "/tmp/unit/resources/");
    CHECK(folder_of_file_uri("file:///tmp/unit/resources/") == "/tmp/unit/resources/");
    CHECK(folder_of_file_uri("file:/tmp/unit/resources") == "/tmp/unit/resources/");
    CHECK(folder_of_file_uri("file://localhost/tmp/a%20b/r") == "/tmp/a b/r/");
    CHECK(folder_of_file_uri("file:///tmp/%C3%A9t%C3%A9") == "/tmp/\xC3\xA9t\xC3\xA9/");
    CHECK(!folder_of_file_uri("http://host/r"));
    CHECK(!folder_of_file_uri("file://otherhost/r"));
    CHECK(!folder_of_file_uri("file:///tmp/bad%2"));
    CHECK(!folder_of_file_uri("file:///tmp/bad%zz"));
    CHECK(!folder_of_file_uri("file:relative/path"));
}
