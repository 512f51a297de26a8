// The grammar has no left recursion and no rule that can loop without consuming input.
#include "grammar/model_grammar.hpp"

#include <doctest/doctest.h>
#include <tao/pegtl/contrib/analyze.hpp>

TEST_CASE("the model grammar passes PEGTL's analysis") {
    CHECK(tao::pegtl::analyze<yamsc::grammar::model_file>(1) == 0);
}

TEST_CASE("the standalone expression grammar passes PEGTL's analysis") {
    CHECK(tao::pegtl::analyze<yamsc::grammar::standalone_expression>(1) == 0);
}
