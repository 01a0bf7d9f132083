:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for consistency (ORO-SPEC §6.1 safeAdd/update, §6.2
    checkConsistency, vectors of §13.5): one unit per concern.

      - the socket vectors of §13.5 (test ontology);
      - each kind of inconsistency, found by the full check
        (oro_consistent/1, oro_conflict/2) and by the incremental one
        (oro_safe_add/4, oro_consistent_with/2), directly and through
        inferred types and values (domains, sub-properties,
        transitivity, OWL 2 RL class expressions and chains), and its
        consistent counterpart;
      - the incremental check agreeing with the full one statement by
        statement;
      - checkConsistency and safeAdd after plain changes: the verdict
        carried over by the delta log (incremental check of what was
        added, nothing to check for removals) where it can be, a full
        check where it cannot, and always the full check's answer;
      - update on functional properties;
      - the remembered verdict following every change;
      - safeAdd with a memory profile over the socket;
      - an inconsistent model still answering every request.

    Fixtures: test/fixtures/testsuite.ttl, test/fixtures/rl_conflicts.ttl.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_consistency.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(random)).
:- use_module(library(settings)).
:- use_module(library(debug)).
:- use_module(library(oro/oro_memory)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/parse/oro_parse)).

%   Stores: the test ontology, or the fixture of conflicts.

cons_testsuite :-
    test_store_testsuite.

cons_conflicts :-
    test_fixture('rl_conflicts.ttl', File),
    oro_init([commonsense(false), ontologies([File])]).

%   cons_kinds(-Kinds): the sorted functors of the conflicts of myself.

cons_kinds(Kinds) :-
    findall(K, ( oro_conflict(myself, C), functor(C, K, _) ), Ks),
    sort(Ks, Kinds).

%   cons_case(+Base, +Bad, -Result): Base added to a fresh conflicts
%   store must be consistent; then Result is
%   r(ConsistentWith, SafeAdded, BadVisible, ConsistentAfterAdd, Kinds):
%   whether checkConsistency(Bad) holds, what safeAdd(Bad) answered,
%   whether Bad's first statement is visible afterwards, and after a
%   plain add of Bad, whether the model is consistent and the kinds of
%   its conflicts.

cons_case(Base, Bad, r(With, Safe, Visible, After, Kinds)) :-
    cons_conflicts,
    oro_add(myself, Base),
    (   oro_consistent(myself)
    ->  true
    ;   cons_kinds(K0),
        throw(cons_base_inconsistent(Base, K0))
    ),
    test_bool(oro_consistent_with(myself, Bad), With),
    oro_safe_add(myself, Bad, longterm, Safe),
    Bad = [First|_],
    test_bool(oro_check(myself, [First]), Visible),
    oro_add(myself, Bad),
    test_bool(oro_consistent(myself), After),
    cons_kinds(Kinds).

%   cons_ok(+Base, +Good): Good keeps the model consistent, whichever
%   way it is added.

cons_ok(Base, Good) :-
    cons_case(Base, Good, r(true, true, true, true, [])).

%   cons_candidates(-Statements): statements over the conflicts
%   fixture, some conflicting with others.

cons_candidates([ "q1 rdf:type Rock", "q1 grows moss", "q2 grows moss",
                  "q3 rdf:type Solid", "q3 rdf:type Liquid", "q4 rdf:type Slush",
                  "kid hasMother alice", "kid hasMother ally", "ally owl:sameAs alice",
                  "kid hasMother beth", "h1 isBiggerThan h2", "h2 isBiggerThan h3",
                  "h3 isBiggerThan h1", "h3 isBiggerThan h4", "k1 isParentOf k2",
                  "k2 isParentOf k3", "k3 isGrandparentOf k1", "k1 isGrandparentOf k3",
                  "cel rdf:type Cellar", "cel stores q2", "cel stores q5",
                  "cv rdf:type Carnivore", "cv feedsOn q6", "q6 grows moss",
                  "rb rdf:type Robot", "rb hasMother factory2",
                  "rb2 hasMother factory2", "rb2 rdf:type Robot",
                  "me likes tea", "me adores tea", "me hates tea", "me hates milk",
                  "n2 rdf:type Impossible", "tagged wears tag9", "alice wears tag9"
                ]).

%   cons_checks(:Goal, -Kinds): run Goal and collect the kinds of the
%   checks oro_consistency made meanwhile (`full`, `incremental`,
%   `unchanged`), from its debug messages (not printed meanwhile).

:- multifile prolog:debug_print_hook/3.
:- dynamic cons_recording/0, cons_check_kind/1.

prolog:debug_print_hook(oro(consistency), _, Args0) :-
    cons_recording,
    strip_module(Args0, _, Args),
    (   Args = [_, _, _, Kind]
    ->  assertz(cons_check_kind(Kind))
    ;   true
    ).

:- meta_predicate cons_checks(0, -).

cons_checks(Goal, Kinds) :-
    retractall(cons_check_kind(_)),
    setup_call_cleanup(
        ( assertz(cons_recording),
          debug(oro(consistency))
        ),
        once(Goal),
        ( nodebug(oro(consistency)),
          retractall(cons_recording)
        )),
    findall(K, retract(cons_check_kind(K)), Kinds).

%   cons_verdict_checks(-Verdict, -Kinds): checkConsistency and the
%   kinds of check it made.

cons_verdict_checks(Verdict, Kinds) :-
    cons_checks(test_bool(oro_consistent(myself), Verdict), Kinds).

%   cons_full(-Verdict): the verdict of a full check, whatever is
%   remembered.

cons_full(Verdict) :-
    test_bool(\+ oro_conflict(myself, _), Verdict).


                 /*******************************
                 *       §13.5 OVER SOCKETS     *
                 *******************************/

:- begin_tests(consistency_vectors,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

cons_fresh :-
    test_ok(reset, []).

%   cons_fresh_long_units(-Units): cons_fresh with memory time units of
%   1,000 s (Units, the previous length, to restore): a short-term fact
%   lives 10,000 s, so a test never depends on how fast it runs.

cons_fresh_long_units(Units) :-
    setting(oro_memory:time_base, Units),
    set_setting(oro_memory:time_base, 1000000),
    cons_fresh.

%   cons_profiles(+Statement, -Profiles): the memory profiles in which
%   the asserted Statement has a deadline (none for long-term facts).

cons_profiles(Statement, Profiles) :-
    oro_statements([Statement], [rdf(S, P, O)], _),
    oro_memory_deadlines(myself, Deadlines),
    findall(Profile, member(_-rdf(S, P, O)-Profile, Deadlines), Profiles0),
    sort(Profiles0, Profiles).

%   cons_in_graph(+Statement, +Profile, -Bool): Statement is stored in
%   the graph of Profile of myself.

cons_in_graph(Statement, Profile, Bool) :-
    oro_statements([Statement], [rdf(S, P, O)], _),
    oro_graph(myself, profile(Profile), Graph),
    test_bool(rdf(S, P, O, Graph), Bool).

test(disjoint_added_and_cleared,
     [ setup(cons_fresh),
       true(Values == ["true", "false", "true"])
     ]) :-
    test_ok(checkConsistency, [], V1),
    test_ok(add, ['[cow rdf:type Plant]']),
    test_ok(checkConsistency, [], V2),
    test_ok(clear, ['[cow rdf:type Plant]']),
    test_ok(checkConsistency, [], V3),
    Values = [V1, V2, V3].
test(complement_through_domain,
     [ setup(cons_fresh),
       true(Values == ["false", "true"])
     ]) :-
    test_ok(add, ['[cow climbsOn banana_tree]']),
    test_ok(checkConsistency, [], V1),
    test_ok(clear, ['[cow climbsOn banana_tree]']),
    test_ok(checkConsistency, [], V2),
    Values = [V1, V2].
test(functional_values_replaced,
     [ setup(cons_fresh),
       true(V == "true")
     ]) :-
    test_ok(clear, ['[gorilla age 12, gorilla weight 100.2]']),
    test_ok(add, ['[gorilla age 21, gorilla weight 99.5]']),
    test_ok(checkConsistency, [], V).
test(functional_two_ages,
     [ setup(cons_fresh),
       true(V == "false")
     ]) :-
    test_ok(add, ['[gorilla age 21]']),
    test_ok(checkConsistency, [], V).
test(safe_add,
     [ setup(cons_fresh),
       true(Values == ["true", "false", "true", "false"])
     ]) :-
    test_ok(safeAdd, ['[horse rdf:type oro:Animal]'], V1),
    test_ok(safeAdd, ['[horse rdf:type Plant]'], V2),
    test_ok(check, ['[horse rdf:type Animal]'], V3),
    test_ok(check, ['[horse rdf:type Plant]'], V4),
    Values = [V1, V2, V3, V4].
test(check_consistency_of_statements,
     [ setup(cons_fresh),
       true(Values == ["true", "false", "false"])
     ]) :-
    test_ok(checkConsistency, ['[cow drinks water]'], V1),
    test_ok(checkConsistency, ['[cow rdf:type Plant]'], V2),
    test_ok(check, ['[cow drinks water]'], V3),
    Values = [V1, V2, V3].
test(patterns_refused_as_by_add,
     [ setup(cons_fresh),
       true(Replies == [Refused, Refused, Refused, ok("false")])
     ]) :-
    Refused = error("laas.openrobots.ontology.exceptions.IllegalStatementException",
                    "A complete statement is expected here, not a pattern: \c
                     ?x rdf:type Monkey."),
    test_call(checkConsistency, ['[?x rdf:type Monkey]'], R1),
    test_call(safeAdd, ['[?x rdf:type Monkey]'], R2),
    test_call(add, ['[?x rdf:type Monkey]'], R3),
    test_call(check, ['[coco rdf:type Monkey]'], R4),
    Replies = [R1, R2, R3, R4].
test(update,
     [ setup(cons_fresh),
       true(Values == ["true", ["21"], ["99.5"],
                       ["KingKong", "Lord of the rings"], ["99"], ["true"]])
     ]) :-
    test_ok(add, ['[gorilla rdfs:label "KingKong"]']),
    test_ok(update, ['[gorilla age 21, gorilla weight 99.5]']),
    test_ok(checkConsistency, [], C),
    test_set_call(find, [a, '[gorilla age ?a, gorilla weight ?w]'], A1),
    test_set_call(find, [w, '[gorilla age ?a, gorilla weight ?w]'], W1),
    test_ok(update, ['[gorilla age 99, gorilla rdfs:label "Lord of the rings", \c
                      gorilla likeIcecream true]']),
    Patterns = '[gorilla age ?a, gorilla rdfs:label ?l, gorilla likeIcecream ?c]',
    test_set_call(find, [l, Patterns], L),
    test_set_call(find, [a, Patterns], A2),
    test_set_call(find, [c, Patterns], C2),
    Values = [C, A1, W1, L, A2, C2].
test(safe_add_short_term,
     [ setup(cons_fresh_long_units(Units)),
       cleanup(set_setting(oro_memory:time_base, Units)),
       true(Values == ["true", [shortterm], true, "false", [shortterm], [], false])
     ]) :-
    test_ok(safeAdd, ['[horse rdf:type Animal]', 'SHORTTERM'], V1),
    cons_profiles("horse rdf:type Animal", P1),
    cons_in_graph("horse rdf:type Animal", shortterm, G1),
    test_ok(safeAdd, ['[mule rdf:type Animal, mule rdf:type Plant]', 'shortterm'], V2),
    cons_profiles("mule rdf:type Animal", P2),
    cons_profiles("mule rdf:type Plant", P3),
    test_bool(oro_check(myself, ["mule rdf:type Plant"]), G3),
    Values = [V1, P1, G1, V2, P2, P3, G3].
test(safe_add_long_term_by_default,
     [ setup(cons_fresh),
       true(Values == ["true", [], true])
     ]) :-
    test_ok(safeAdd, ['[horse rdf:type Animal]'], V1),
    cons_profiles("horse rdf:type Animal", P1),
    cons_in_graph("horse rdf:type Animal", longterm, G1),
    Values = [V1, P1, G1].
test(safe_add_refused_while_inconsistent,
     [ setup(cons_fresh),
       true(Values == ["false", "false", "true", "true"])
     ]) :-
    test_ok(add, ['[cow rdf:type Plant]']),
    test_ok(safeAdd, ['[horse rdf:type Animal]'], V1),
    test_ok(check, ['[horse rdf:type Animal]'], V2),
    test_ok(remove, ['[cow rdf:type Plant]']),
    test_ok(safeAdd, ['[horse rdf:type Animal]'], V3),
    test_ok(check, ['[horse rdf:type Animal]'], V4),
    Values = [V1, V2, V3, V4].

:- end_tests(consistency_vectors).


                 /*******************************
                 *     KINDS OF CONFLICT        *
                 *******************************/

%   Each test: Base (consistent), then Bad through checkConsistency(Bad),
%   safeAdd(Bad), and a plain add.  Expected r(false, false, false,
%   false, [Kind]) for a conflict.

:- begin_tests(consistency_kinds).

test(disjoint_with,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["r1 rdf:type Mineral"], ["r1 rdf:type Vegetable"], R).
test(disjoint_with_sub_class_and_domain,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["r1 rdf:type Rock"], ["r1 grows moss"], R).
test(disjoint_with_other_individual, []) :-
    cons_ok(["r1 rdf:type Rock"], ["r2 grows moss"]).
test(all_disjoint_classes,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["w1 rdf:type Solid"], ["w1 rdf:type Gas"], R).
test(all_disjoint_classes_other_members, []) :-
    cons_ok(["w1 rdf:type Solid"], ["w2 rdf:type Gas"]).
test(complement_of,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["f1 rdf:type Fake"], ["f1 rdf:type Genuine"], R).
test(complement_of_other_individual, []) :-
    cons_ok(["f1 rdf:type Fake"], ["f2 rdf:type Genuine"]).
test(nothing,
     [ true(R == r(false, false, false, false, [nothing])) ]) :-
    cons_case(["n0 rdf:type Genuine"], ["n1 rdf:type Impossible"], R).
test(nothing_through_sub_class,
     [ true(R == r(false, false, false, false, [nothing])) ]) :-
    cons_case(["n0 rdf:type Fiction"], ["u1 rdf:type Unicorn"], R).
test(nothing_super_class_ok, []) :-
    cons_ok(["n0 rdf:type Genuine"], ["n1 rdf:type Fiction"]).
test(functional_literals,
     [ true(R == r(false, false, false, false, [functional])) ]) :-
    cons_case(["bob birthYear 1990"], ["bob birthYear 1991"], R).
test(functional_same_value_other_datatype, []) :-
    cons_ok(["bob birthYear 1990"], ["bob birthYear \"1990.0\"^^xsd:double"]).
test(functional_individuals_open_world, []) :-
    cons_ok(["kid hasMother m1"], ["kid hasMother m2"]).
test(functional_individuals_different_from,
     [ true(R == r(false, false, false, false, [functional])) ]) :-
    cons_case(["kid hasMother m1", "m1 owl:differentFrom m2"],
              ["kid hasMother m2"], R).
test(functional_individuals_all_different,
     [ true(R == r(false, false, false, false, [functional])) ]) :-
    cons_case(["kid hasMother alice"], ["kid hasMother carol"], R).
test(functional_individuals_same_as, []) :-
    cons_ok(["kid hasMother alice", "ally owl:sameAs alice"],
            ["kid hasMother ally"]).
test(functional_through_same_as_and_different,
     [ true(R == r(false, false, false, false, [functional])) ]) :-
    cons_case(["kid hasMother alice", "bee owl:sameAs beth"],
              ["kid hasMother bee"], R).
test(inverse_functional_open_world, []) :-
    cons_ok(["t1 wears tag1"], ["t2 wears tag1"]).
test(inverse_functional_individuals,
     [ true(R == r(false, false, false, false, [inverse_functional])) ]) :-
    cons_case(["alice wears tag1"], ["beth wears tag1"], R).
test(inverse_functional_literal,
     [ true(R == r(false, false, false, false, [inverse_functional])) ]) :-
    cons_case(["p1 hasSerial \"X1\"", "p1 owl:differentFrom p2"],
              ["p2 hasSerial \"X1\""], R).
test(same_as_and_different_from,
     [ true(R == r(false, false, false, false, [same_and_different])) ]) :-
    cons_case(["x1 owl:differentFrom y1"], ["x1 owl:sameAs y1"], R).
test(same_as_and_different_from_others_ok, []) :-
    cons_ok(["x1 owl:differentFrom y1"], ["x1 owl:sameAs z1", "z1 owl:sameAs w1"]).
test(same_as_and_all_different_others_ok, []) :-
    cons_ok(["al owl:sameAs alice"], ["al owl:sameAs ally", "bo owl:sameAs beth"]).
test(same_as_and_all_different,
     [ true(R == r(false, false, false, false, [same_and_different])) ]) :-
    cons_case(["al owl:sameAs alice"], ["al owl:sameAs carol"], R).
test(asymmetric,
     [ true(R == r(false, false, false, false, [asymmetric])) ]) :-
    cons_case(["a1 isParentOf b1"], ["b1 isParentOf a1"], R).
test(asymmetric_one_way, []) :-
    cons_ok(["a1 isParentOf b1"], ["b1 isParentOf c1"]).
test(irreflexive,
     [ true(R == r(false, false, false, false, [irreflexive])) ]) :-
    cons_case(["big1 isBiggerThan small1"], ["big1 isBiggerThan big1"], R).
test(irreflexive_through_transitivity,
     [ true(R == r(false, false, false, false, [irreflexive])) ]) :-
    cons_case(["e1 isBiggerThan e2", "e2 isBiggerThan e3"],
              ["e3 isBiggerThan e1"], R).
test(irreflexive_transitive_chain_ok, []) :-
    cons_ok(["e1 isBiggerThan e2", "e2 isBiggerThan e3"],
            ["e3 isBiggerThan e4"]).
test(property_disjoint,
     [ true(R == r(false, false, false, false, [disjoint_properties])) ]) :-
    cons_case(["ann likes tea"], ["ann hates tea"], R).
test(property_disjoint_through_sub_property,
     [ true(R == r(false, false, false, false, [disjoint_properties])) ]) :-
    cons_case(["ann hates coffee"], ["ann adores coffee"], R).
test(property_disjoint_other_value, []) :-
    cons_ok(["ann likes tea"], ["ann hates coffee"]).

:- end_tests(consistency_kinds).


                 /*******************************
                 *     THROUGH RL INFERENCES    *
                 *******************************/

:- begin_tests(consistency_rl).

test(all_values_from,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["cellar1 rdf:type Cellar", "t1 grows moss"],
              ["cellar1 stores t1"], R).
test(all_values_from_other_place, []) :-
    cons_ok(["cellar1 rdf:type Cellar", "t1 grows moss"],
            ["attic1 stores t1"]).
test(all_values_from_type_added_last,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["cellar1 stores t1", "t1 grows moss"],
              ["cellar1 rdf:type Cellar"], R).
test(some_values_from,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["c1 rdf:type Carnivore", "c1 feedsOn p1"],
              ["p1 grows seeds"], R).
test(some_values_from_no_vegetable, []) :-
    cons_ok(["c1 rdf:type Carnivore", "c1 feedsOn p1"],
            ["p1 rdf:type Rock"]).
test(has_value_functional,
     [ true(R == r(false, false, false, false, [functional])) ]) :-
    cons_case(["rb1 rdf:type Robot"], ["rb1 hasMother factory2"], R).
test(has_value_functional_same_value, []) :-
    cons_ok(["rb1 rdf:type Robot"], ["rb1 hasMother factory1"]).
test(has_value_type_added_last,
     [ true(R == r(false, false, false, false, [functional])) ]) :-
    cons_case(["rb1 hasMother factory2"], ["rb1 rdf:type Robot"], R).
test(intersection,
     [ true(R == r(false, false, false, false, [disjoint])) ]) :-
    cons_case(["s0 rdf:type Solid"], ["s1 rdf:type Slush"], R).
test(chain_asymmetric,
     [ true(R == r(false, false, false, false, [asymmetric])) ]) :-
    cons_case(["g1 isParentOf g2", "g2 isParentOf g3"],
              ["g3 isGrandparentOf g1"], R).
test(chain_asymmetric_link_added_last,
     [ true(R == r(false, false, false, false, [asymmetric])) ]) :-
    cons_case(["g1 isParentOf g2", "g3 isGrandparentOf g1"],
              ["g2 isParentOf g3"], R).
test(chain_ok, []) :-
    cons_ok(["g1 isParentOf g2", "g2 isParentOf g3"],
            ["g1 isGrandparentOf g3"]).

:- end_tests(consistency_rl).


                 /*******************************
                 *   INCREMENTAL = FULL CHECK   *
                 *******************************/

%   Statement by statement, safeAdd (incremental) keeps exactly those
%   a full check after a plain add accepts.

:- begin_tests(consistency_incremental).


cons_full_verdict(Statement, Verdict) :-
    oro_add(myself, [Statement]),
    (   oro_consistent(myself)
    ->  Verdict = true
    ;   Verdict = false,
        oro_remove(myself, [Statement])
    ).

test(agrees, [ setup(cons_conflicts),
               true(Safe == Full)
             ]) :-
    cons_candidates(Statements),
    maplist([S, V]>>oro_safe_add(myself, [S], longterm, V), Statements, Safe),
    assertion(oro_consistent(myself)),
    cons_conflicts,
    maplist(cons_full_verdict, Statements, Full).
test(batch_keeps_the_consistent_ones,
     [ setup(cons_conflicts),
       true(Kept == [true, false, true])
     ]) :-
    oro_safe_add(myself, ["q1 rdf:type Rock", "q1 grows moss", "q2 grows moss"],
                 longterm, Accepted),
    assertion(Accepted == false),
    maplist([S, B]>>test_bool(oro_check(myself, [S]), B),
            ["q1 rdf:type Rock", "q1 grows moss", "q2 grows moss"], Kept).

%   rdf_db keeps one term for the literals of one datatype and value,
%   spelled as the first one asserted: 0.50 is stored as the 0.5 of
%   cup9 (hasCharacteristicWeight is functional in the common-sense
%   ontology).

test(rejected_literal_spelled_otherwise_not_kept,
     [ setup(oro_init([])),
       true(r(Accepted, Kept, Full) == r(false, false, true))
     ]) :-
    oro_add(myself, ["cup1 hasCharacteristicWeight 0.7",
                     "cup9 hasCharacteristicWeight 0.5"]),
    oro_safe_add(myself, ["cup1 hasCharacteristicWeight 0.50"], longterm,
                 Accepted),
    test_bool(oro_check(myself, ["cup1 hasCharacteristicWeight 0.5"]), Kept),
    cons_full(Full).
test(known_literal_spelled_otherwise_left_alone,
     [ setup(oro_init([])),
       true(r(Accepted, Holds, Deadlines) == r(false, true, []))
     ]) :-
    % Known already, the first statement is not added again (with a
    % deadline) when the second is rejected.
    oro_add(myself, ["cup2 hasCharacteristicWeight 0.5"]),
    oro_safe_add(myself, ["cup2 hasCharacteristicWeight 0.50",
                          "cup2 hasCharacteristicWeight 0.7"],
                 'SHORTTERM', Accepted),
    test_bool(oro_check(myself, ["cup2 hasCharacteristicWeight 0.5"]), Holds),
    oro_memory_deadlines(myself, Deadlines).

:- end_tests(consistency_incremental).


                 /*******************************
                 *   VERDICTS AFTER A CHANGE    *
                 *******************************/

%   After a plain add or remove, the remembered verdict is carried over
%   through the delta log: an incremental check of what was added, no
%   check for what was removed; a full check where the log cannot tell.
%   Each test also compares the verdict with a full check's.

:- begin_tests(consistency_delta).

test(check_after_add_is_incremental,
     [ setup(cons_conflicts),
       true(R == [true-[full], true-[incremental], true, false-[incremental], false])
     ]) :-
    cons_verdict_checks(V1, K1),
    oro_add(myself, ["r1 rdf:type Rock"]),
    cons_verdict_checks(V2, K2),
    cons_full(F2),
    oro_add(myself, ["r1 grows moss"]),
    cons_verdict_checks(V3, K3),
    cons_full(F3),
    R = [V1-K1, V2-K2, F2, V3-K3, F3].
test(safe_add_after_add_is_incremental,
     [ setup(cons_conflicts),
       true(R == [true-[incremental], false-[incremental], false])
     ]) :-
    assertion(oro_consistent(myself)),
    oro_add(myself, ["w1 rdf:type Solid"]),
    cons_checks(oro_safe_add(myself, ["w2 rdf:type Gas"], longterm, A1), K1),
    oro_add(myself, ["w3 rdf:type Solid"]),
    cons_checks(oro_safe_add(myself, ["w3 rdf:type Gas"], longterm, A2), K2),
    test_bool(oro_check(myself, ["w3 rdf:type Gas"]), Kept),
    R = [A1-K1, A2-K2, Kept].
test(check_consistency_of_statements_after_add,
     [ setup(cons_conflicts),
       true(R == [false-[incremental], true-[]])
     ]) :-
    assertion(oro_consistent(myself)),
    oro_add(myself, ["w1 rdf:type Solid"]),
    cons_checks(test_bool(oro_consistent_with(myself, ["w1 rdf:type Gas"]), V1), K1),
    cons_checks(test_bool(oro_consistent_with(myself, ["w2 rdf:type Gas"]), V2), K2),
    R = [V1-K1, V2-K2].
test(removal_needs_no_check,
     [ setup(cons_conflicts),
       true(R == [true-[incremental], true])
     ]) :-
    oro_add(myself, ["r1 rdf:type Rock", "r2 grows moss"]),
    assertion(oro_consistent(myself)),
    oro_remove(myself, ["r1 rdf:type Rock"]),
    cons_verdict_checks(V, K),
    cons_full(F),
    R = [V-K, F].
test(inconsistent_stays_so_after_adds,
     [ setup(cons_conflicts),
       true(R == [false-[unchanged], false])
     ]) :-
    oro_add(myself, ["r1 rdf:type Rock", "r1 grows moss"]),
    assertion(\+ oro_consistent(myself)),
    oro_add(myself, ["r2 grows moss"]),
    cons_verdict_checks(V, K),
    cons_full(F),
    R = [V-K, F].
test(removal_from_inconsistent_is_a_full_check,
     [ setup(cons_conflicts),
       true(R == [true-[full], true])
     ]) :-
    oro_add(myself, ["r1 rdf:type Rock", "r1 grows moss"]),
    assertion(\+ oro_consistent(myself)),
    oro_remove(myself, ["r1 grows moss"]),
    cons_verdict_checks(V, K),
    cons_full(F),
    R = [V-K, F].
test(update_is_incremental,
     [ setup(cons_conflicts),
       true(R == [true-[incremental], true])
     ]) :-
    oro_add(myself, ["kid hasMother alice"]),
    assertion(oro_consistent(myself)),
    oro_update(myself, ["kid hasMother beth"]),
    cons_verdict_checks(V, K),
    cons_full(F),
    R = [V-K, F].
test(schema_change_is_a_full_check,
     [ setup(cons_conflicts),
       true(R == [false-[full], true-[full]])
     ]) :-
    oro_add(myself, ["w1 rdf:type Solid", "w1 rdf:type Crystal"]),
    assertion(oro_consistent(myself)),
    oro_add(myself, ["Crystal owl:disjointWith Solid"]),
    cons_verdict_checks(V1, K1),
    oro_remove(myself, ["Crystal owl:disjointWith Solid"]),
    cons_verdict_checks(V2, K2),
    R = [V1-K1, V2-K2].
test(unmasked_ontology_triple_is_an_addition,
     [ setup(cons_testsuite),
       true(R == [true, true-[incremental], false-[incremental], false])
     ]) :-
    oro_remove(myself, ["gorilla age 12"]),
    test_bool(oro_consistent(myself), V1),
    oro_add(myself, ["gorilla age 21"]),
    cons_verdict_checks(V2, K2),
    oro_add(myself, ["gorilla age 12"]),        % the ontology's triple again
    cons_verdict_checks(V3, K3),
    cons_full(F3),
    R = [V1, V2-K2, V3-K3, F3].
test(other_models_changes,
     [ setup(cons_conflicts),
       true(R == [true-[incremental], false])
     ]) :-
    oro_create_agent(other, other),
    assertion(oro_consistent(myself)),
    oro_add(other, ["w1 rdf:type Solid", "w1 rdf:type Gas"]),
    cons_verdict_checks(V1, K1),
    test_bool(oro_consistent(other), V2),
    R = [V1-K1, V2].
test(reset_forgets,
     [ setup(cons_conflicts),
       true(R == [false, true])
     ]) :-
    oro_add(myself, ["w1 rdf:type Solid", "w1 rdf:type Gas"]),
    test_bool(oro_consistent(myself), V1),
    oro_reset,
    test_bool(oro_consistent(myself), V2),
    R = [V1, V2].
test(large_delta_is_a_full_check,
     [ setup(cons_conflicts),
       true(R == [true-[full], false-[incremental]])
     ]) :-
    assertion(oro_consistent(myself)),
    findall(S, ( between(1, 1100, I),
                 format(string(S), "stone~d rdf:type Rock", [I])
               ), Stones),
    oro_add(myself, Stones),
    cons_verdict_checks(V1, K1),
    oro_add(myself, ["stone7 grows moss"]),
    oro_add(myself, Stones),                % nothing new, nothing logged
    cons_verdict_checks(V2, K2),
    R = [V1-K1, V2-K2].

%   Random adds, removes and updates of the candidate statements: after
%   each, the remembered (incremental) verdict is the full check's.

cons_random_change(Statements) :-
    random_member(S, Statements),
    random_between(1, 10, R),
    (   R =< 1
    ->  oro_update(myself, [S])
    ;   oro_check(myself, [S])
    ->  oro_remove(myself, [S])
    ;   oro_add(myself, [S])
    ).

test(random_changes_agree,
     [ setup(cons_conflicts),
       true(Disagreements-Kinds == []-[full, incremental, unchanged])
     ]) :-
    cons_candidates(Statements),
    set_random(seed(5)),
    findall(Kind-(N-V-F),
            ( between(1, 300, N),
              cons_random_change(Statements),
              cons_verdict_checks(V, Ks),
              member(Kind, Ks),
              cons_full(F)
            ), Results),
    findall(N-V-F, ( member(_-(N-V-F), Results), V \== F ), Disagreements),
    pairs_keys(Results, Kinds0),
    sort(Kinds0, Kinds).

:- end_tests(consistency_delta).


                 /*******************************
                 *     UPDATE, CACHED VERDICT   *
                 *******************************/

:- begin_tests(consistency_update).

test(update_replaces_functional_literal,
     [ setup(cons_conflicts),
       true(Values-Consistent == ['1991']-true)
     ]) :-
    oro_add(myself, ["bob birthYear 1990"]),
    oro_update(myself, ["bob birthYear 1991"]),
    test_find(myself, y, ["bob birthYear ?y"], Values),
    test_bool(oro_consistent(myself), Consistent).
test(update_replaces_functional_resource,
     [ setup(cons_conflicts),
       true(Values-Consistent == [beth]-true)
     ]) :-
    oro_add(myself, ["kid hasMother alice"]),
    oro_update(myself, ["kid hasMother beth"]),
    test_find(myself, m, ["kid hasMother ?m"], Values),
    test_bool(oro_consistent(myself), Consistent).
test(add_of_second_value_is_inconsistent,
     [ setup(cons_conflicts),
       fail
     ]) :-
    oro_add(myself, ["kid hasMother alice"]),
    oro_add(myself, ["kid hasMother beth"]),
    oro_consistent(myself).

:- end_tests(consistency_update).

:- begin_tests(consistency_verdict).

test(follows_changes,
     [ setup(cons_conflicts),
       true(Verdicts == [true, true, false, false, true, true])
     ]) :-
    test_bool(oro_consistent(myself), V1),
    test_bool(oro_consistent(myself), V2),
    oro_add(myself, ["w1 rdf:type Solid", "w1 rdf:type Gas"]),
    test_bool(oro_consistent(myself), V3),
    test_bool(oro_consistent(myself), V4),
    oro_remove(myself, ["w1 rdf:type Gas"]),
    test_bool(oro_consistent(myself), V5),
    test_bool(oro_consistent(myself), V6),
    Verdicts = [V1, V2, V3, V4, V5, V6].
test(schema_change,
     [ setup(cons_conflicts),
       true(Verdicts == [true, false, true])
     ]) :-
    oro_add(myself, ["w1 rdf:type Solid", "w1 rdf:type Crystal"]),
    test_bool(oro_consistent(myself), V1),
    oro_add(myself, ["Crystal owl:disjointWith Solid"]),
    test_bool(oro_consistent(myself), V2),
    oro_remove(myself, ["Crystal owl:disjointWith Solid"]),
    test_bool(oro_consistent(myself), V3),
    Verdicts = [V1, V2, V3].
test(safe_add_after_unsafe_add,
     [ setup(cons_conflicts),
       true(Accepted == false)
     ]) :-
    oro_safe_add(myself, ["w1 rdf:type Solid"], longterm, true),
    oro_add(myself, ["w1 rdf:type Gas"]),
    oro_safe_add(myself, ["w9 rdf:type Solid"], longterm, Accepted).
test(per_model,
     [ setup(cons_conflicts),
       true(Verdicts == [false, true])
     ]) :-
    oro_create_agent(other, other),
    oro_add(myself, ["w1 rdf:type Solid", "w1 rdf:type Gas"]),
    test_bool(oro_consistent(myself), V1),
    test_bool(oro_consistent(other), V2),
    Verdicts = [V1, V2].

:- end_tests(consistency_verdict).


                 /*******************************
                 *   AN INCONSISTENT MODEL      *
                 *******************************/

%   While inconsistent the server answers reads over what is there,
%   says false to checkConsistency and keeps sending events.

:- begin_tests(consistency_inconsistent_model,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

test(keeps_answering,
     [ setup(test_ok(reset, [])),
       true(Values == ["false", "true", ["cow", "gorilla"], ["Animal", "Plant"],
                       "false", true, "false"])
     ]) :-
    test_ok(add, ['[cow rdf:type Plant, gorilla eats grass]']),
    test_ok(checkConsistency, [], V1),
    test_ok(check, ['[cow rdf:type Plant, cow rdf:type Animal]'], V2),
    test_set_call(find, [x, '[?x eats grass]'], V3),
    test_call(getClassesOf, [cow], Reply),
    test_map(Reply, Pairs),
    findall(C, ( member(C-_, Pairs), memberchk(C, ["Animal", "Plant"]) ), V4),
    test_ok(safeAdd, ['[horse rdf:type Animal]'], V5),
    test_set_call(lookup, [cow], Found),
    test_bool(memberchk(["cow", "INSTANCE"], Found), V6),
    test_ok(checkConsistency, [], V7),
    Values = [V1, V2, V3, V4, V5, V6, V7].
test(events_keep_working,
     [ setup(test_ok(reset, [])),
       true(Event = event(Id, _))
     ]) :-
    test_ok(add, ['[cow rdf:type Plant]']),
    test_connected(C,
                   ( oro_call(C, registerEvent,
                              ['FACT_CHECKING', 'ON_TRUE', '[sheep eats grass]'],
                              ok(Id)),
                     oro_call(C, add, ['[sheep eats grass]'], ok(_)),
                     oro_next_event(C, Event, 10)
                   )).

:- end_tests(consistency_inconsistent_model).

%   Once a verdict was remembered, the delta log's monitor notes every
%   commit: that leaves no clause behind for the clause garbage
%   collector (see oro_store, "Writes leave no clause behind").

:- begin_tests(consistency_clause_churn,
               [ setup(oro_init([])),
                 cleanup(oro_init([]))
               ]).

test(logged_adds_retract_no_clause, true(Reclaimed < 20)) :-
    assertion(oro_consistent(myself)),
    test_churn_adds(warm, _),
    test_churn_adds(probe, Reclaimed).

:- end_tests(consistency_clause_churn).
