:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(debug)).
:- use_module('../server/oro_server').
:- use_module('../server/oro_methods').
:- use_module('../prolog/oro').
:- use_module('../prolog/oro/oro_parse').

/*  Requests answered ahead (server/oro_server.pl, REQUESTS AHEAD): a
    client that sends its requests back to back has the next one
    prepared (oro_methods:oro_prepare/3) while a helper thread of its
    connection answers the previous one.

    ahead_prepare checks, in process, that a prepared request is
    answered as the dispatcher answers it.

    Run: swipl -g run_tests -t halt test/test_ahead.pl
*/

                 /*******************************
                 *           PREPARED           *
                 *******************************/

:- begin_tests(ahead_prepare,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

%   Each request, prepared then performed, gets the reply the
%   dispatcher gives; the store is reset before each of the two.

test(prepared_as_dispatched, true(Differ == [])) :-
    findall(M-Ps, prepare_case(M, Ps), Cases),
    include(differs, Cases, Differ).
test(statements_parsed_ahead, true(Atoms == true)) :-
    oro_prepare("add", ["[\"ahead1 isOn table1\"]"], prepared(_, add, Args)),
    (   Args = [[rdf(S, P, O)]],
        maplist(atom, [S, P, O])
    ->  Atoms = true
    ;   Atoms = Args
    ).
test(statements_parsed_ahead_any_case, true(Name-Args = add-[[rdf(_, _, _)]])) :-
    oro_prepare("ADD", ["[\"ahead1 isOn table1\"]"], prepared(_, Name, Args)).
test(agent_statements_parsed_ahead, true(Args = ["human1", [rdf(_, _, _)]])) :-
    oro_prepare("addForAgent", ["human1", "[\"ahead1 isOn table1\"]"],
                prepared(_, addForAgent, Args)).
test(pattern_left_as_text, true(Args == [["ahead1 isOn ?x"]])) :-
    oro_prepare("add", ["[\"ahead1 isOn ?x\"]"], prepared(_, add, Args)).
test(bad_statement_left_as_text, true(Args == [["ahead1 isOn"]])) :-
    oro_prepare("add", ["[\"ahead1 isOn\"]"], prepared(_, add, Args)).
test(find_not_parsed, true(Args == ["x", ["?x isOn table1"]])) :-
    oro_prepare("find", ["x", "[?x isOn table1]"], prepared(_, find, Args)).
test(unknown_method_not_prepared, true(P == request("nosuch", []))) :-
    oro_prepare("nosuch", [], P).
test(bad_set_not_prepared, true(P == request("add", ["[a b"]))) :-
    oro_prepare("add", ["[a b"], P).

%   Parsed statements, given again as triples, are the same triples: the
%   method then stores what it would have stored from the text.

test(parsed_statements_normal, true(Differ == [])) :-
    findall(S, normal_case(S), Statements),
    exclude(parsed_again_same, Statements, Differ).

:- end_tests(ahead_prepare).

prepare_case("add", ["[\"ahead1 isOn table1\", \"ahead2 rdfs:label \\\"a b\\\"\"]"]).
prepare_case("ADD", ["[\"ahead1 isOn table1\"]"]).
prepare_case("add", ["[\"ahead1 isOn\"]"]).
prepare_case("add", ["[\"ahead1 isOn ?x\"]"]).
prepare_case("add", ["[a b"]).
prepare_case("add", ["[\"ahead1 isOn table1\"]", "LONGTERM"]).
prepare_case("add", ["[\"ahead1 isOn table1\"]", "NOSUCH"]).
prepare_case("update", ["[\"ahead1 isOn table1\"]"]).
prepare_case("addForAgent", ["nobody", "[\"ahead1 isOn table1\"]"]).
prepare_case("check", ["[\"ahead1 isOn table1\"]"]).
prepare_case("find", ["x", "[?x isOn table1]"]).
prepare_case("nosuch", []).
prepare_case("hello", ["extra"]).
prepare_case("hello", []).

differs(Method-Params) :-
    test_ok(reset, []),
    test_server_context(Context),
    oro_dispatch(Context, Method, Params, Dispatched),
    test_ok(reset, []),
    oro_prepare(Method, Params, Prepared),
    oro_perform(Context, Prepared, Performed),
    Dispatched \== Performed.

test_server_context(_{peer:test, mutex:none, end:true, subscribers:slot([]),
                      max_params:4096}).

normal_case("ahead1 isOn table1").
normal_case("ahead1 rdfs:label \"a table\"").
normal_case("ahead1 rdfs:label \"une table\"@fr").
normal_case("ahead1 hasWeight 12").
normal_case("ahead1 hasWeight 1.5").
normal_case("ahead1 isVisible true").
normal_case("ahead1 hasName \"x\"^^xsd:string").
normal_case("ahead1 rdf:type oro:Table").
normal_case("ahead1 owl:sameAs ahead2").
normal_case("ahead1 isOn http://example.org/t#table1").
normal_case("ahead1 rdfs:comment \"quote \\\" and tab\\t\"").

parsed_again_same(Statement) :-
    oro_statements([Statement], Triples, []),
    oro_statements(Triples, Again, []),
    Again == Triples.
