/*  Tests of the Prolog API for today's semweb code: rdf11 literal
    terms in and (on request) out, the sentences the toplevel prints for
    oro's errors, oro_show/1,2 and oro_models/0.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro)).
:- use_module(library(oro/oro_errors)).

api_store :-
    oro_init([]),
    oro_add(myself, ["fork1 rdf:type Fork", "fork1 isOn kitchen_table"]).

api_lines(Goal, Lines) :-
    with_output_to(string(Text), Goal),
    split_string(Text, "\n", "", Lines0),
    exclude(==(""), Lines0, Lines).

api_message(Formal, Text) :-
    message_to_codes(error(Formal, _), Text).

message_to_codes(Term, Text) :-
    '$messages':translate_message(Term, Lines, []),
    with_output_to(string(Text),
                   print_message_lines(current_output, '', Lines)).

:- begin_tests(api_rdf11_in, [setup(api_store), cleanup(api_store)]).

test(typed_value, true(Found == true)) :-
    oro_add(myself, [rdf(cup1, weight, 150^^xsd:int)]),
    test_bool(oro_check(myself, ["cup1 weight 150"]), Found).
test(typed_lexical_string, true(Found == true)) :-
    oro_add(myself, [rdf(cup2, weight, "150"^^xsd:int)]),
    test_bool(oro_check(myself, [rdf(cup2, weight, 150)]), Found).
test(string_literal, true(Found == true)) :-
    oro_add(myself, [rdf(cup3, note, "blue"^^xsd:string)]),
    test_bool(oro_check(myself, ["cup3 note \"blue\""]), Found).
test(language_tag, true(Label == tasse)) :-
    oro_add(myself, [rdf(cup4, rdfs:label, "tasse"@fr)]),
    oro_label(myself, cup4, fr, Label).
test(boolean_and_date, true(Found == true)) :-
    oro_add(myself, [ rdf(cup5, clean, true^^xsd:boolean),
                      rdf(cup5, made, date(2020, 1, 2)^^xsd:date)
                    ]),
    test_bool(oro_check(myself, [ "cup5 clean true",
                                  "cup5 made 2020-01-02^^xsd:date"
                                ]), Found).
test(in_patterns, true(Subjects-Held == [Cup]-[Cup])) :-
    rdf_global_id(oro:cup6, Cup),
    oro_add(myself, [rdf(cup6, weight, 7^^xsd:int)]),
    oro_find(myself, X, [rdf(X, weight, 7^^xsd:int)], Subjects),
    findall(S, oro_holds(myself, S, weight, 7^^xsd:int), Held).
test(bad_lexical, error(syntax_error(oro_lexical_form(_, _)))) :-
    oro_add(myself, [rdf(cup7, weight, "heavy"^^xsd:int)]).
test(variable_value, error(instantiation_error)) :-
    oro_add(myself, [rdf(cup7, weight, _^^xsd:int)]).

:- end_tests(api_rdf11_in).

:- begin_tests(api_rdf11_out, [setup(api_store), cleanup(api_store)]).

test(values, true(Values == [150^^Int])) :-
    rdf_equal(xsd:int, Int),
    oro_add(myself, ["cup1 weight 150"]),
    oro_find(myself, w, ["cup1 weight ?w"], Values0),
    oro_rdf11(Values0, Values).
test(lang_and_plain, true(Out == ["tasse"@fr, "x"^^String])) :-
    rdf_equal(xsd:string, String),
    oro_rdf11([literal(lang(fr, tasse)), literal(x)], Out).
test(triples_and_iris, true(Out == [rdf(a, p, 2.5^^Double)])) :-
    rdf_equal(xsd:double, Double),
    oro_rdf11([rdf(a, p, literal(type(Double, '2.5')))], Out).
test(round_trip, true(Found == true)) :-
    oro_add(myself, ["cup2 made 2020-01-02^^xsd:date"]),
    oro_find(myself, d, ["cup2 made ?d"], [D0]),
    oro_rdf11(D0, D),
    test_bool(oro_check(myself, [rdf(cup2, made, D)]), Found).

:- end_tests(api_rdf11_out).

%   Every oro error term has a sentence: for each clause of the tables
%   of oro_errors, prolog:error_message//1 gives the table's text.

api_error_formal(Formal) :-
    clause(oro_errors:error_table(Formal, _, _, _), _),
    \+ ( copy_term(Formal, Copy),
         term_variables(Copy, Vars),
         maplist(=(x), Vars),
         oro_errors:own_message(Copy)
       ).
api_error_formal(Formal) :-
    clause(oro_errors:api_error(Formal, _, _), _).

api_translated(Formal) :-
    copy_term(Formal, Copy),
    term_variables(Copy, Vars),
    maplist(=(x), Vars),
    phrase(prolog:error_message(Copy), [Format-_]),
    (   clause(oro_errors:error_table(Formal, _, Format, _), _)
    ;   clause(oro_errors:api_error(Formal, Format, _), _)
    ),
    !.

:- begin_tests(api_messages).

test(statement_tokens,
     true(Text == "Three tokens are expected in a statement, 1 found in foo.")) :-
    catch(oro_add(myself, ["foo"]), E, true),
    message_to_codes(E, Text0),
    split_string(Text0, "", "\n", [Text]).
test(every_error_term, true(Untranslated == [])) :-
    findall(Formal, api_error_formal(Formal), Formals),
    assertion(Formals \== []),
    exclude(api_translated, Formals, Untranslated).
test(swi_errors_keep_their_text, true(Said == true)) :-
    api_message(existence_error(source_sink, '/no/file'), Text),
    test_bool(sub_string(Text, _, _, _, "does not exist"), Said).

:- end_tests(api_messages).

:- begin_tests(api_toplevel, [setup(api_store), cleanup(api_store)]).

test(show_asserted_and_inferred,
     true(Lines == [ "fork1 (instance) in myself",
                     "  labels:     none",
                     "  classes:    Fork (asserted); owl:Thing (inferred)",
                     "  statements:",
                     "    fork1 isOn kitchen_table              asserted",
                     "    fork1 isAt kitchen_table              inferred",
                     "    fork1 owl:sameAs fork1                inferred"
                   ])) :-
    api_lines(oro_show(fork1), Lines).
test(show_in_agent_model, true(Head == "fork1 (instance) in myself")) :-
    api_lines(oro_show(default, oro:fork1), [Head|_]).
test(show_unknown, error(existence_error(resource, _))) :-
    oro_show(no_such_thing).
test(models, true(Line == "myself                   3          0         0         0")) :-
    api_lines(oro_models, Lines),
    member(Line, Lines),
    sub_string(Line, 0, _, _, "myself"),
    !.

:- end_tests(api_toplevel).
