/*  The W3C SPARQL test suites (../shared/w3c-sparql/, see its README)
    run through the HTTP endpoint of a server on an ephemeral port:
    every applicable query-evaluation test (SPARQL 1.0 data-r2, SPARQL
    1.1 query and result-format folders) with infer=false and the
    test's data as default-graph-uri / named-graph-uri, and every
    syntax test.  test/oro_w3c_sparql.pl runs them; the tests that
    fail today are listed with their reason in test/w3c_sparql_known.pl
    (and in the README's table).

    The unit fails if a test not in that list fails (a regression) or
    if a listed test passes (the list and the README must then be
    updated).  The whole run takes about 3 s on a 2-core VM.  It prints
    the pass table per category; ORO_W3C_VERBOSE=1 also prints each
    failure.  Skipped, with a notice, when ../shared is absent.
*/

:- use_module(library(plunit)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(oro_test_support).
:- use_module(oro_w3c_sparql).
:- use_module(w3c_sparql_known).

w3c_present :-
    (   w3c_suite_dir(_)
    ->  true
    ;   print_message(informational,
                      format("../shared/w3c-sparql is absent: W3C SPARQL \c
                              suites skipped", [])),
        format(user_error, "Notice: ../shared/w3c-sparql is absent: \c
                            the W3C SPARQL suites are skipped~n", []),
        fail
    ).

%   w3c_outcomes(-Outcomes): each Category-Name-Outcome-Detail.

w3c_outcomes(Outcomes) :-
    w3c_suite_dir(Dir),
    w3c_tests(Dir, Tests),
    test_server_http_port(Port),
    findall(o(Category, Name, Outcome, Detail),
            ( member(Test, Tests),
              w3c_category(Test, Category),
              arg(3, Test, Name),
              w3c_run(Port, Test, Outcome, Detail)
            ),
            Outcomes).

print_table(Outcomes) :-
    findall(C, member(o(C, _, _, _), Outcomes), Cs0),
    sort(Cs0, Cs),
    format(user_error, "~n| category | passed | tests |~n|---|---|---|~n", []),
    forall(member(C, Cs),
           ( aggregate_all(count, member(o(C, _, pass, _), Outcomes), P),
             aggregate_all(count, member(o(C, _, _, _), Outcomes), N),
             format(user_error, "| ~w | ~d | ~d |~n", [C, P, N])
           )),
    aggregate_all(count, member(o(_, _, pass, _), Outcomes), TP),
    length(Outcomes, TN),
    format(user_error, "| **all** | **~d** | **~d** |~n", [TP, TN]),
    (   getenv('ORO_W3C_VERBOSE', _)
    ->  forall(member(o(C, Name, fail, Detail), Outcomes),
               format(user_error, "FAIL ~w | ~w | ~s~n", [C, Name, Detail]))
    ;   true
    ).

w3c_setup :-
    test_server_start([commonsense(false), http(0)]).

:- begin_tests(w3c_sparql, [ condition(w3c_present),
                             setup(w3c_setup),
                             cleanup(test_server_stop)
                           ]).

test(suites, [true(Unexpected-Fixed == []-[])]) :-
    w3c_outcomes(Outcomes),
    print_table(Outcomes),
    findall(C-N, ( member(o(C, N, fail, _), Outcomes),
                   \+ w3c_known_failure(C, N, _)
                 ), Unexpected),
    findall(C-N, ( member(o(C, N, pass, _), Outcomes),
                   w3c_known_failure(C, N, _)
                 ), Fixed).

:- end_tests(w3c_sparql).
