:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for the inference closure (ORO-SPEC §5, §11): what oro_holds/4,
    oro_type/3, oro_check/2 and oro_find/4 derive from asserted triples,
    with schema from the test ontology (test/fixtures/testsuite.ttl), from
    the common-sense ontology, or added at run time; and removal taking
    away exactly the inferences it supported.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_reasoning.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).

%   Fresh stores: the test ontology alone, or the common-sense one.

reasoning_testsuite :-
    test_store_testsuite.

reasoning_commonsense :-
    oro_init([]).

%   reasoning_types(+Name, -Classes): the contracted classes of Name.

reasoning_types(Name, Classes) :-
    oro_name_iri(Name, X),
    findall(C, ( oro_type(myself, X, C0), oro_iri_name(C0, C) ), Classes0),
    sort(Classes0, Classes).


                 /*******************************
                 *          SUBCLASSES          *
                 *******************************/

:- begin_tests(subclass_closure).

test(asserted_type, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["gorilla rdf:type Monkey"]).
test(inherited_type, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["gorilla rdf:type Animal"]).
test(inherited_type_term, [setup(reasoning_testsuite)]) :-
    oro_type(myself, oro:gorilla, oro:'Animal').
test(everything_is_a_thing, [setup(reasoning_testsuite)]) :-
    oro_type(myself, oro:gorilla, owl:'Thing').
test(not_entailed, [setup(reasoning_testsuite), fail]) :-
    oro_check(myself, ["gorilla rdf:type Plant"]).
test(transitive_three_levels, [setup(reasoning_testsuite), nondet]) :-
    oro_subclass(myself, oro:'F', oro:'A').
test(lattice_types_of_f, [ setup(reasoning_testsuite),
                           true(Classes == ['A', 'B', 'C', 'D', 'E', 'F',
                                            'owl:NamedIndividual',
                                            'owl:Thing'])
                         ]) :-
    reasoning_types(f, Classes).
test(instances_of_a, [ setup(reasoning_testsuite),
                       true(Xs == [e, f, j, k])
                     ]) :-
    test_find(myself, x, ["?x rdf:type A"], Xs).
test(find_monkeys, [ setup(reasoning_testsuite),
                     true(Xs == [baboon, gorilla])
                   ]) :-
    test_find(myself, x, ["?x rdf:type Monkey"], Xs).
test(find_animals, [ setup(reasoning_testsuite),
                     true(Xs == [baboon, cow, gorilla])
                   ]) :-
    test_find(myself, x, ["?x rdf:type Animal"], Xs).
test(subclass_statement_holds, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["Monkey rdfs:subClassOf Animal",
                       "F rdfs:subClassOf A"]).
test(superclasses_by_find, [ setup(reasoning_testsuite),
                             true(Cs == ['Animal', 'Monkey', 'owl:Thing'])
                           ]) :-
    test_find(myself, c, ["Monkey rdfs:subClassOf ?c"], Cs).

:- end_tests(subclass_closure).


                 /*******************************
                 *       DOMAIN AND RANGE       *
                 *******************************/

:- begin_tests(domain_range).

test(domain, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["sparrow eats seeds"]),
    oro_type(myself, oro:sparrow, oro:'Animal').
test(range, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["apple rdf:type Plant"]).
test(range_added, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["sparrow eats seeds"]),
    oro_type(myself, oro:seeds, oro:'Plant').
test(domain_of_sub_property,
     [ setup(reasoning_testsuite),
       true(Classes == ['Animal', 'Monkey', 'owl:Thing'])
     ]) :-
    oro_add(myself, ["bumbo climbsOn old_oak"]),
    reasoning_types(bumbo, Classes).
test(range_of_sub_property,
     [ setup(reasoning_testsuite),
       true(Classes == ['Plant', 'owl:Thing'])
     ]) :-
    oro_add(myself, ["bumbo climbsOn old_oak"]),
    reasoning_types(old_oak, Classes).
test(domain_through_inverse, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["rock isUnder snail"]),
    oro_check(myself, ["snail rdf:type Animal"]).
test(no_domain_on_object, [setup(reasoning_testsuite), fail]) :-
    oro_add(myself, ["rock isUnder snail"]),
    oro_check(myself, ["rock rdf:type Animal"]).
test(find_by_domain, [ setup(reasoning_testsuite),
                       true(Xs == [baboon, cow, gorilla, sheep])
                     ]) :-
    oro_add(myself, ["sheep eats grass"]),
    test_find(myself, animals, ["?animals rdf:type Animal"], Xs).
test(join_checks_types_each_way,
     [ setup(reasoning_testsuite),
       true(Animals-Plants == [felix, sheep, snail]-[hay])
     ]) :-
    oro_add(myself, ["stone isAt rock", "snail isOn rock", "sheep isAt rock",
                     "sheep eats hay", "hay isAt rock", "felix isAt rock",
                     "felix rdf:type Monkey"]),
    test_find(myself, a, ["?a isAt rock", "?a rdf:type Animal"], Animals),
    test_find(myself, p, ["?p isAt rock", "?p rdf:type Plant"], Plants).
test(datatype_range_types_nothing, [ setup(reasoning_testsuite),
                                     true(Classes == ['Animal', 'owl:Thing'])
                                   ]) :-
    oro_add(myself, ["dolly age 3"]),
    reasoning_types(dolly, Classes).

:- end_tests(domain_range).


                 /*******************************
                 *        SUB-PROPERTIES        *
                 *******************************/

:- begin_tests(sub_property).

test(chain_declared, [setup(reasoning_testsuite), nondet]) :-
    oro_subproperty(myself, oro:climbsOn, oro:isAt).
test(one_level, [setup(reasoning_testsuite)]) :-
    oro_holds(myself, oro:baboon, oro:isOn, oro:banana_tree).
test(two_levels, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["baboon isAt banana_tree"]).
test(predicates_between, [ setup(reasoning_testsuite),
                           true(Ps == [climbsOn, isAt, isOn])
                         ]) :-
    test_find(myself, p, ["baboon ?p banana_tree"], Ps).
test(super_property_not_down, [setup(reasoning_testsuite), fail]) :-
    oro_add(myself, ["cat isOn mat"]),
    oro_check(myself, ["cat climbsOn mat"]).
test(inverse_of_super_property, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["banana_tree isUnder baboon"]).
test(sub_property_added, [ setup(reasoning_testsuite),
                           true(Xs == [mouse])
                         ]) :-
    oro_add(myself, ["nibbles rdfs:subPropertyOf eats",
                     "mouse nibbles cheese"]),
    oro_check(myself, ["mouse eats cheese",
                       "mouse rdf:type Animal",
                       "cheese rdf:type Plant"]),
    test_find(myself, x, ["?x eats cheese"], Xs).

:- end_tests(sub_property).


                 /*******************************
                 *           INVERSES           *
                 *******************************/

:- begin_tests(inverse_of).

test(ontology_fact, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["cow isOn grass"]).
test(ontology_fact_holds, [setup(reasoning_testsuite)]) :-
    oro_holds(myself, oro:cow, oro:isOn, oro:grass).
test(find_inverse, [ setup(reasoning_testsuite),
                     true(Xs == [cow])
                   ]) :-
    test_find(myself, x, ["?x isOn grass"], Xs).
test(added_both_ways, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["stone isUnder frog", "frog isOn lily"]),
    oro_check(myself, ["frog isOn stone", "lily isUnder frog"]).
test(apple_under_nothing, [ setup(reasoning_testsuite),
                            true(Xs == [])
                          ]) :-
    test_find(myself, x, ["apple isUnder ?x"], Xs).
test(inverse_declared_at_run_time, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["isEatenBy owl:inverseOf eats"]),
    oro_check(myself, ["apple isEatenBy gorilla", "grass isEatenBy cow"]).

:- end_tests(inverse_of).


                 /*******************************
                 *         TRANSITIVITY         *
                 *******************************/

:- begin_tests(transitive).

reasoning_chain :-
    reasoning_testsuite,
    oro_add(myself, ["a1 isOn a2", "a2 isOn a3", "a3 isOn a4"]).

test(closed, [setup(reasoning_chain)]) :-
    oro_holds(myself, oro:a1, oro:isOn, oro:a4).
test(closed_super_property, [setup(reasoning_chain)]) :-
    oro_check(myself, ["a1 isAt a4"]).
test(ends_forward, [ setup(reasoning_chain),
                     true(Xs == [a2, a3, a4])
                   ]) :-
    test_find(myself, x, ["a1 isAt ?x"], Xs).
test(ends_backward, [ setup(reasoning_chain),
                      true(Xs == [a1, a2, a3])
                    ]) :-
    test_find(myself, x, ["?x isAt a4"], Xs).
test(inverse_transitive, [ setup(reasoning_chain),
                           true(Xs == [a1, a2, a3])
                         ]) :-
    test_find(myself, x, ["a4 isUnder ?x"], Xs).
test(holds_enumerates, [ setup(reasoning_chain),
                         true(Xs == [a2, a3, a4])
                       ]) :-
    findall(X, oro_holds(myself, oro:a1, oro:isOn, X), Xs0),
    maplist(oro_iri_name, Xs0, Xs1),
    sort(Xs1, Xs).
test(not_reflexive, [setup(reasoning_chain), fail]) :-
    oro_check(myself, ["a1 isAt a1"]).
test(not_backwards, [setup(reasoning_chain), fail]) :-
    oro_check(myself, ["a4 isOn a1"]).
test(non_transitive_not_closed, [setup(reasoning_testsuite), fail]) :-
    oro_add(myself, ["fox eats hen", "hen eats grain"]),
    oro_check(myself, ["fox eats grain"]).
test(declared_at_run_time, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["knows rdf:type owl:TransitiveProperty",
                     "alice knows bob", "bob knows carol"]),
    oro_check(myself, ["alice knows carol"]).
test(cycle_terminates, [ setup(reasoning_testsuite),
                         true(Xs == [c1, c2])
                       ]) :-
    oro_add(myself, ["c1 isAt c2", "c2 isAt c1"]),
    test_find(myself, x, ["c1 isAt ?x"], Xs).

:- end_tests(transitive).


                 /*******************************
                 *           SYMMETRY           *
                 *******************************/

:- begin_tests(symmetric).

test(both_ways, [setup(reasoning_commonsense)]) :-
    oro_add(myself, ["cup1 isNextTo plate1"]),
    oro_check(myself, ["plate1 isNextTo cup1"]).
test(holds_both_ways, [setup(reasoning_commonsense)]) :-
    oro_add(myself, ["cup1 isNextTo plate1"]),
    oro_holds(myself, oro:plate1, oro:isNextTo, oro:cup1).
test(find_both_ways, [ setup(reasoning_commonsense),
                       true(Xs == [cup1, spoon1])
                     ]) :-
    oro_add(myself, ["cup1 isNextTo plate1", "plate1 isNextTo spoon1"]),
    test_find(myself, x, ["plate1 isNextTo ?x"], Xs).
test(not_transitive, [setup(reasoning_commonsense), fail]) :-
    oro_add(myself, ["cup1 isNextTo plate1", "plate1 isNextTo spoon1"]),
    oro_check(myself, ["cup1 isNextTo spoon1"]).
test(asymmetric_by_default, [setup(reasoning_commonsense), fail]) :-
    oro_add(myself, ["cup1 isOn table1"]),
    oro_check(myself, ["table1 isOn cup1"]).
test(declared_at_run_time, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["marriedTo rdf:type owl:SymmetricProperty",
                     "tarzan marriedTo jane"]),
    oro_check(myself, ["jane marriedTo tarzan"]).

:- end_tests(symmetric).


                 /*******************************
                 *          EQUIVALENCE         *
                 *******************************/

:- begin_tests(equivalence).

test(equivalent_class_forward, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["Ape owl:equivalentClass Monkey"]),
    oro_check(myself, ["gorilla rdf:type Ape"]).
test(equivalent_class_backward, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["Ape owl:equivalentClass Monkey", "kong rdf:type Ape"]),
    oro_check(myself, ["kong rdf:type Monkey", "kong rdf:type Animal"]).
test(equivalent_class_instances, [ setup(reasoning_testsuite),
                                   true(Xs == [baboon, gorilla, kong])
                                 ]) :-
    oro_add(myself, ["Ape owl:equivalentClass Monkey", "kong rdf:type Ape"]),
    test_find(myself, x, ["?x rdf:type Ape"], Xs).
test(equivalent_classes_subclasses, [setup(reasoning_testsuite), nondet]) :-
    oro_add(myself, ["Ape owl:equivalentClass Monkey"]),
    oro_subclass(myself, oro:'Ape', oro:'Monkey'),
    oro_subclass(myself, oro:'Monkey', oro:'Ape').
test(equivalent_property_forward, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["devours owl:equivalentProperty eats"]),
    oro_check(myself, ["gorilla devours apple"]).
test(equivalent_property_backward, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["devours owl:equivalentProperty eats",
                     "lion devours zebra"]),
    oro_check(myself, ["lion eats zebra",
                       "lion rdf:type Animal",
                       "zebra rdf:type Plant"]).

:- end_tests(equivalence).


                 /*******************************
                 *            SAME AS           *
                 *******************************/

:- begin_tests(same_as).

reasoning_kong :-
    reasoning_testsuite,
    oro_add(myself, ["kingkong owl:sameAs gorilla", "kk owl:sameAs kingkong"]).

test(asserted, [setup(reasoning_kong)]) :-
    oro_check(myself, ["kingkong owl:sameAs gorilla"]).
test(symmetric, [setup(reasoning_kong)]) :-
    oro_check(myself, ["gorilla owl:sameAs kingkong"]).
test(transitive, [setup(reasoning_kong)]) :-
    oro_check(myself, ["kk owl:sameAs gorilla", "gorilla owl:sameAs kk"]).
test(reflexive_class, [ setup(reasoning_kong),
                        true(Xs == [gorilla, kingkong, kk])
                      ]) :-
    test_find(myself, x, ["?x owl:sameAs gorilla"], Xs).
test(types_shared, [setup(reasoning_kong)]) :-
    oro_check(myself, ["kk rdf:type Monkey", "kk rdf:type Animal"]).
test(facts_shared, [setup(reasoning_kong)]) :-
    oro_check(myself, ["kk eats apple", "kingkong age 12"]).
test(facts_shared_back, [setup(reasoning_kong)]) :-
    oro_add(myself, ["kk likes bananas"]),
    oro_check(myself, ["gorilla likes bananas"]).
test(find_substitutes, [ setup(reasoning_kong),
                         true(Xs == [gorilla, kingkong, kk])
                       ]) :-
    test_find(myself, x, ["?x eats apple"], Xs).
test(find_object_substitutes, [ setup(reasoning_testsuite),
                                 true(Xs == [gorilla])
                               ]) :-
    oro_add(myself, ["malus owl:sameAs apple"]),
    test_find(myself, x, ["?x eats malus"], Xs).
test(distinct_individuals_not_same, [setup(reasoning_kong), fail]) :-
    oro_check(myself, ["kk owl:sameAs cow"]).
test(unlinked, [setup(reasoning_kong), fail]) :-
    oro_remove(myself, ["kk owl:sameAs kingkong"]),
    oro_check(myself, ["kk eats apple"]).

:- end_tests(same_as).


                 /*******************************
                 *      SCHEMA AT RUN TIME      *
                 *******************************/

:- begin_tests(runtime_schema).

test(subclass_then_instance, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["Insect rdfs:subClassOf Animal"]),
    oro_add(myself, ["ladybug rdf:type Insect"]),
    oro_check(myself, ["ladybug rdf:type Animal"]).
test(instance_then_subclass, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["ladybug rdf:type Insect"]),
    \+ oro_check(myself, ["ladybug rdf:type Animal"]),
    oro_add(myself, ["Insect rdfs:subClassOf Animal"]),
    oro_check(myself, ["ladybug rdf:type Animal"]).
test(find_sees_new_class, [ setup(reasoning_testsuite),
                            true(Xs == [baboon, cow, gorilla, ladybug])
                          ]) :-
    oro_add(myself, ["Insect rdfs:subClassOf Animal",
                     "ladybug rdf:type Insect"]),
    test_find(myself, x, ["?x rdf:type Animal"], Xs).
test(domain_added, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["paris likes dancing"]),
    \+ oro_check(myself, ["paris rdf:type Animal"]),
    oro_add(myself, ["likes rdfs:domain Animal"]),
    oro_check(myself, ["paris rdf:type Animal"]).
test(range_added, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["paris likes dancing", "likes rdfs:range Activity"]),
    oro_check(myself, ["dancing rdf:type Activity"]).

:- end_tests(runtime_schema).


                 /*******************************
                 *            REMOVAL           *
                 *******************************/

:- begin_tests(removal).

reasoning_ladybug :-
    reasoning_testsuite,
    oro_add(myself, ["Insect rdfs:subClassOf Animal",
                     "ladybug rdf:type Insect"]).

test(subclass_axiom_removed, [setup(reasoning_ladybug), fail]) :-
    oro_remove(myself, ["Insect rdfs:subClassOf Animal"]),
    oro_check(myself, ["ladybug rdf:type Animal"]).
test(asserted_type_stays, [setup(reasoning_ladybug)]) :-
    oro_remove(myself, ["Insect rdfs:subClassOf Animal"]),
    oro_check(myself, ["ladybug rdf:type Insect"]).
test(other_support_keeps, [setup(reasoning_ladybug)]) :-
    oro_add(myself, ["ladybug eats aphids"]),
    oro_remove(myself, ["Insect rdfs:subClassOf Animal"]),
    oro_check(myself, ["ladybug rdf:type Animal"]).
test(last_support_removed, [setup(reasoning_ladybug), fail]) :-
    oro_add(myself, ["ladybug eats aphids"]),
    oro_remove(myself, ["Insect rdfs:subClassOf Animal"]),
    oro_remove(myself, ["ladybug eats aphids"]),
    oro_check(myself, ["ladybug rdf:type Animal"]).
test(domain_fact_removed, [setup(reasoning_testsuite), fail]) :-
    oro_add(myself, ["sparrow eats seeds"]),
    oro_remove(myself, ["sparrow eats seeds"]),
    oro_check(myself, ["sparrow rdf:type Animal"]).
test(ontology_domain_removed,
     [ setup(reasoning_testsuite),
       true(Classes == ['Animal', 'owl:Thing'])
     ]) :-
    oro_add(myself, ["bumbo climbsOn old_oak"]),
    oro_remove(myself, ["climbsOn rdfs:domain Monkey"]),
    reasoning_types(bumbo, Classes).
test(chain_link_removed, [ setup(reasoning_testsuite),
                           true(Xs == [a2])
                         ]) :-
    oro_add(myself, ["a1 isOn a2", "a2 isOn a3", "a3 isOn a4"]),
    oro_remove(myself, ["a2 isOn a3"]),
    test_find(myself, x, ["a1 isAt ?x"], Xs).
test(inferred_not_removable, [setup(reasoning_testsuite)]) :-
    oro_remove(myself, ["gorilla rdf:type Animal"]),
    oro_check(myself, ["gorilla rdf:type Animal"]).
test(same_as_removed, [ setup(reasoning_testsuite),
                        true(Xs == [gorilla])
                      ]) :-
    oro_add(myself, ["kingkong owl:sameAs gorilla"]),
    oro_remove(myself, ["kingkong owl:sameAs gorilla"]),
    test_find(myself, x, ["?x eats apple"], Xs).

:- end_tests(removal).


                 /*******************************
                 *       LITERAL MATCHING       *
                 *******************************/

:- begin_tests(literal_values).

test(int_value, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["gorilla age 12"]).
test(int_value_find, [ setup(reasoning_testsuite),
                       true(Xs == [cow, gorilla])
                     ]) :-
    test_find(myself, x, ["?x age 12"], Xs).
test(int_typed_explicitly, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["gorilla age \"12\"^^xsd:int"]).
test(int_other_numeric_type,
     [ setup(reasoning_testsuite)
     ]) :-
    oro_check(myself, ["gorilla age 12^^xsd:integer"]).
test(int_other_numeric_type_find,
     [ setup(reasoning_testsuite),
       true(Xs == [cow, gorilla])
     ]) :-
    test_find(myself, x, ["?x age 12^^xsd:integer"], Xs).
test(other_value, [setup(reasoning_testsuite), fail]) :-
    oro_check(myself, ["gorilla age 13"]).
test(double_value, [setup(reasoning_testsuite)]) :-
    oro_check(myself, ["baboon weight 48.5"]).
test(boolean_value, [ setup(reasoning_testsuite),
                      true(Xs == [baboon])
                    ]) :-
    test_find(myself, x, ["?x isFemale true"], Xs).
test(boolean_false, [setup(reasoning_testsuite), fail]) :-
    oro_check(myself, ["gorilla isFemale true"]).
test(value_lexical_form, [ setup(reasoning_testsuite),
                           true(As == ['12'])
                         ]) :-
    test_find(myself, a, ["gorilla age ?a"], As).
test(labels_lexical_forms, [ setup(reasoning_testsuite),
                             true(Ls == ['baboon monkey', babouin])
                           ]) :-
    test_find(myself, l, ["baboon rdfs:label ?l"], Ls).
test(string_matches_en_label,
     [ setup(reasoning_testsuite)
     ]) :-
    oro_check(myself, ["baboon rdfs:label \"baboon monkey\""]).
test(find_string_matches_en_label,
     [ setup(reasoning_testsuite),
       true(Xs == [baboon])
     ]) :-
    test_find(myself, x, ["?x rdfs:label \"baboon monkey\""], Xs).
test(find_string_matches_fr_label,
     [ setup(reasoning_testsuite),
       true(Xs == [baboon])
     ]) :-
    test_find(myself, x, ["?x rdfs:label 'babouin'"], Xs).
test(added_string_label, [ setup(reasoning_testsuite),
                           true(Xs == [gorilla])
                         ]) :-
    oro_add(myself, ["gorilla rdfs:label \"king kong\""]),
    test_find(myself, x, ["?x rdfs:label \"king kong\""], Xs).
test(unsigned_short_by_value, [setup(reasoning_testsuite)]) :-
    oro_add(myself, ["gorilla legs \"2\"^^xsd:unsignedShort"]),
    oro_check(myself, ["gorilla legs 2"]).
test(same_value_canonical_text, [ setup(reasoning_testsuite),
                                  true(Texts == ['7', '150.0'])
                                ]) :-
    oro_add(myself, ["x1 v \"+7\"^^xsd:int", "y1 v 7",
                     "x2 v \"150\"^^xsd:double", "y2 v 150.0"]),
    oro_find(myself, o, ["y1 v ?o"], [V1]),
    oro_find(myself, o, ["y2 v ?o"], [V2]),
    maplist(oro_term_text, [V1, V2], Texts).
test(term_number_pattern, [ setup(reasoning_testsuite),
                            true(Xs == [cow, gorilla])
                          ]) :-
    oro_find(myself, X, [rdf(X, age, 12)], Values),
    maplist(oro_term_text, Values, Xs).

:- end_tests(literal_values).


                 /*******************************
                 *      PINNED SCHEMA TABLES    *
                 *******************************/

:- use_module(library(oro/reason/oro_reason),
              [ oro_with_shared_schema/3,
                oro_shared_schema/2,
                oro_schema_superclass/3
              ]).

:- begin_tests(shared_schema_pin).

%   A thread reads model myself's shared schema tables in a pinned
%   region while two schema changes replace them, each followed by a
%   compilation: its tables stay (they were freed at the second
%   compilation, whatever readers still had them) until it leaves the
%   region, which frees them.

test(tables_kept_while_pinned, [ setup(reasoning_testsuite),
                                 true(Kept-Freed == true-true)
                               ]) :-
    oro_add(myself, ["Gadget rdfs:subClassOf Artifact"]),
    rdf_global_id(oro:'Gadget', Gadget),
    rdf_global_id(oro:'Artifact', Artifact),
    thread_self(Me),
    thread_create(reasoning_pinned_reader(Me), Reader, []),
    call_cleanup(
        (   thread_get_message(Me, pinned_key(Key), [timeout(30)]),
            oro_add(myself, ["Widget rdfs:subClassOf Artifact"]),
            oro_shared_schema(myself, Key1),
            oro_add(myself, ["Gizmo rdfs:subClassOf Artifact"]),
            oro_shared_schema(myself, Key2),
            assertion(Key1 \== Key),
            assertion(Key2 \== Key1),
            test_bool(oro_schema_superclass(Key, Gadget, Artifact), Kept)
        ),
        (   thread_send_message(Reader, leave),
            thread_join(Reader, Status)
        )),
    assertion(Status == true),
    test_bool(test_wait_until(\+ oro_schema_superclass(Key, Gadget,
                                                        Artifact), 10),
              Freed).

%   reasoning_pinned_reader(+Main): send Main the key of myself's shared
%   tables from a pinned region, and leave it when told to (30 s at
%   most).

reasoning_pinned_reader(Main) :-
    thread_self(Me),
    oro_with_shared_schema(myself, Key,
                           ( thread_send_message(Main, pinned_key(Key)),
                             thread_get_message(Me, leave, [timeout(30)])
                           )).

:- end_tests(shared_schema_pin).
