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
      - update on functional properties;
      - the remembered verdict following every change;
      - an inconsistent model still answering every request.

    Fixtures: test/fixtures/testsuite.ttl, test/fixtures/rl_conflicts.ttl.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_consistency.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).

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


                 /*******************************
                 *       §13.5 OVER SOCKETS     *
                 *******************************/

:- begin_tests(consistency_vectors,
               [ setup(test_server_start_testsuite),
                 cleanup(test_server_stop)
               ]).

cons_fresh :-
    test_ok(reset, []).

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
test(nothing,
     [ true(R == r(false, false, false, false, [nothing])) ]) :-
    cons_case(["n0 rdf:type Genuine"], ["n1 rdf:type Impossible"], R).
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

:- end_tests(consistency_incremental).


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
                       "false"])
     ]) :-
    test_ok(add, ['[cow rdf:type Plant, gorilla eats grass]']),
    test_ok(checkConsistency, [], V1),
    test_ok(check, ['[cow rdf:type Plant, cow rdf:type Animal]'], V2),
    test_set_call(find, [x, '[?x eats grass]'], V3),
    test_call(getClassesOf, [cow], Reply),
    test_map(Reply, Pairs),
    findall(C, ( member(C-_, Pairs), memberchk(C, ["Animal", "Plant"]) ), V4),
    test_ok(safeAdd, ['[horse rdf:type Animal]'], V5),
    Values = [V1, V2, V3, V4, V5].
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
