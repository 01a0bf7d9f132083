:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for the OWL 2 RL class reasoning of oro_reason: one unit per
    rule, each in both directions (the inference is made; it is not made
    when a premise is missing), over test/fixtures/rl_classes.ttl:

      - hasValue (cls-hv1, cls-hv2), with resource and literal values;
      - someValuesFrom (cls-svf1, cls-svf2), with class and datatype
        fillers;
      - allValuesFrom (cls-avf);
      - intersectionOf (cls-int1, cls-int2), unionOf (cls-uni), oneOf;
      - property chains (prp-spo2), with super-properties, ranges,
        inverses, inverse links and recursion;
      - cyclic definitions terminating;
      - schema given at run time, removal taking inferences away;
      - the consumers seeing the inferences: find, check, SPARQL,
        taxonomy, categorization, lookup's property types, event
        dependencies;
      - the public OpenRobots ontology (../shared/ontologies/oro.owl,
        skipped with a notice when ../shared is absent).

    Run: cd /work/main && swipl -g run_tests -t halt test/test_owl_rl.pl
*/

:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).

rl_store :-
    test_fixture('rl_classes.ttl', File),
    oro_init([commonsense(false), ontologies([File])]).

rl_with(Statements) :-
    rl_store,
    oro_add(myself, Statements).

rl_holds(Statement) :-
    oro_check(myself, [Statement]).

%   rl_types(+Name, -Classes): the named classes of Name, contracted.

rl_types(Name, Classes) :-
    oro_name_iri(Name, X),
    findall(C, ( oro_type(myself, X, C0),
                 \+ rdf_is_bnode(C0),
                 oro_iri_name(C0, C)
               ), Classes0),
    sort(Classes0, Classes).


                 /*******************************
                 *           HAS VALUE          *
                 *******************************/

:- begin_tests(owl_rl_has_value).

test(value_gives_type, [setup(rl_with(["ball hasColour red"]))]) :-
    rl_holds("ball rdf:type RedObject").
test(other_value_no_type, [setup(rl_with(["ball hasColour blue"])), fail]) :-
    rl_holds("ball rdf:type RedObject").
test(type_gives_value, [setup(rl_with(["tom rdf:type Tomato"]))]) :-
    rl_holds("tom hasColour red").
test(no_type_no_value, [setup(rl_with(["tom rdf:type Fruit"])), fail]) :-
    rl_holds("tom hasColour red").
test(equivalent_type_gives_value, [setup(rl_with(["cherry rdf:type RedObject"]))]) :-
    rl_holds("cherry hasColour red").
test(virtual_value_gives_domain, [setup(rl_with(["tom rdf:type Tomato"]))]) :-
    rl_holds("tom rdf:type ColouredThing").
test(virtual_value_gives_type_back, [setup(rl_with(["tom rdf:type Tomato"]))]) :-
    rl_holds("tom rdf:type RedObject").
test(literal_value_gives_type, [setup(rl_with(["box1 isHolder true"]))]) :-
    rl_holds("box1 rdf:type Holder").
test(other_literal_no_type, [setup(rl_with(["box1 isHolder false"])), fail]) :-
    rl_holds("box1 rdf:type Holder").
test(type_gives_literal_value, [setup(rl_with(["tray1 rdf:type Tray"]))]) :-
    rl_holds("tray1 isHolder true").
test(instances, [ setup(rl_with(["ball hasColour red", "tom rdf:type Tomato",
                                 "sky hasColour blue"])),
                  true(Xs == [ball, tom])
                ]) :-
    test_find(myself, x, ["?x rdf:type RedObject"], Xs).
test(subjects_of_value, [ setup(rl_with(["ball hasColour red", "tom rdf:type Tomato"])),
                          true(Xs == [ball, tom])
                        ]) :-
    test_find(myself, x, ["?x hasColour red"], Xs).
test(values_of_subject, [ setup(rl_with(["tom rdf:type Tomato"])),
                          true(Vs == [red])
                        ]) :-
    test_find(myself, v, ["tom hasColour ?v"], Vs).

:- end_tests(owl_rl_has_value).


                 /*******************************
                 *         SOME VALUES          *
                 *******************************/

:- begin_tests(owl_rl_some_values).

test(thing_filler, [setup(rl_with(["ann hasChild bob"]))]) :-
    rl_holds("ann rdf:type Parent").
test(thing_filler_object_not, [setup(rl_with(["ann hasChild bob"])), fail]) :-
    rl_holds("bob rdf:type Parent").
test(class_filler, [setup(rl_with(["carl owns rex", "rex rdf:type Dog"]))]) :-
    rl_holds("carl rdf:type DogOwner").
test(class_filler_sub_class, [setup(rl_with(["carl owns rex", "rex rdf:type Puppy"]))]) :-
    rl_holds("carl rdf:type DogOwner").
test(class_filler_other_class, [setup(rl_with(["carl owns tom", "tom rdf:type Cat"])), fail]) :-
    rl_holds("carl rdf:type DogOwner").
test(class_filler_type_added_later, [setup(rl_with(["carl owns rex"]))]) :-
    \+ rl_holds("carl rdf:type DogOwner"),
    oro_add(myself, ["rex rdf:type Dog"]),
    rl_holds("carl rdf:type DogOwner").
test(datatype_filler_in_range, [setup(rl_with(["dan age 30"]))]) :-
    rl_holds("dan rdf:type Adult").
test(datatype_filler_bound_included, [setup(rl_with(["dan age 18"]))]) :-
    rl_holds("dan rdf:type Adult").
test(datatype_filler_out_of_range, [setup(rl_with(["eve age 10"])), fail]) :-
    rl_holds("eve rdf:type Adult").
test(datatype_filler_wrong_type, [setup(rl_with(["eve age \"old\""])), fail]) :-
    rl_holds("eve rdf:type Adult").
test(instances, [ setup(rl_with(["carl owns rex", "rex rdf:type Puppy",
                                 "dora owns felix", "felix rdf:type Cat"])),
                  true(Xs == [carl])
                ]) :-
    test_find(myself, x, ["?x rdf:type DogOwner"], Xs).
test(datatype_instances, [ setup(rl_with(["dan age 30", "eve age 10"])),
                           true(Xs == [dan])
                         ]) :-
    test_find(myself, x, ["?x rdf:type Adult"], Xs).

:- end_tests(owl_rl_some_values).


                 /*******************************
                 *          ALL VALUES          *
                 *******************************/

:- begin_tests(owl_rl_all_values).

test(value_typed, [setup(rl_with(["r1 rdf:type VeganRestaurant", "r1 serves salad"]))]) :-
    rl_holds("salad rdf:type VeganDish"),
    rl_holds("salad rdf:type Dish").
test(other_restaurant, [setup(rl_with(["r2 rdf:type Restaurant", "r2 serves steak"])),
                        fail]) :-
    rl_holds("steak rdf:type VeganDish").
test(subject_not_typed, [setup(rl_with(["r1 rdf:type VeganRestaurant", "r1 serves salad"])),
                         fail]) :-
    rl_holds("r1 rdf:type VeganDish").
test(instances, [ setup(rl_with(["r1 rdf:type VeganRestaurant", "r1 serves salad",
                                 "r1 serves soup", "r2 serves steak"])),
                  true(Xs == [salad, soup])
                ]) :-
    test_find(myself, x, ["?x rdf:type Dish"], Xs).

:- end_tests(owl_rl_all_values).


                 /*******************************
                 *  INTERSECTION, UNION, ONE OF *
                 *******************************/

:- begin_tests(owl_rl_class_constructors).

test(intersection_all_members, [setup(rl_with(["ann rdf:type Woman", "ann hasChild bob"]))]) :-
    rl_holds("ann rdf:type Mother").
test(intersection_one_member, [setup(rl_with(["ann rdf:type Woman"])), fail]) :-
    rl_holds("ann rdf:type Mother").
test(intersection_to_members, [ setup(rl_with(["meg rdf:type Mother"])),
                                true(Classes == ['Mother', 'Parent', 'Person',
                                                 'Woman', 'owl:Thing'])
                              ]) :-
    rl_types(meg, Classes).
test(intersection_joined, [ setup(rl_with(["ann rdf:type Woman", "ann hasChild bob",
                                           "zoe rdf:type Woman", "ann knows zoe",
                                           "ann knows bob"])),
                             true(Xs == [ann])
                           ]) :-
    test_find(myself, x, ["ann knows ?x", "?x rdf:type Mother"], Ys),
    test_find(myself, x, ["?x hasChild bob", "?x rdf:type Mother"], Xs),
    assertion(Ys == []).
test(intersection_subclass, [setup(rl_store), nondet]) :-
    oro_subclass(myself, oro:'Mother', oro:'Woman').
test(intersection_instances, [ setup(rl_with(["ann rdf:type Woman", "ann hasChild bob",
                                              "zoe rdf:type Woman", "meg rdf:type Mother"])),
                               true(Xs == [ann, meg])
                             ]) :-
    test_find(myself, x, ["?x rdf:type Mother"], Xs).
test(union_member, [setup(rl_with(["rex rdf:type Puppy"]))]) :-
    rl_holds("rex rdf:type Pet").
test(union_not_member, [setup(rl_with(["star rdf:type Horse"])), fail]) :-
    rl_holds("star rdf:type Pet").
test(union_superclass, [setup(rl_store), nondet]) :-
    oro_subclass(myself, oro:'Cat', oro:'Pet').
test(union_not_down, [setup(rl_with(["pet1 rdf:type Pet"])), fail]) :-
    rl_holds("pet1 rdf:type Dog").
test(one_of, [setup(rl_store)]) :-
    rl_holds("saturday rdf:type WeekendDay").
test(not_one_of, [setup(rl_with(["monday rdf:type Day"])), fail]) :-
    rl_holds("monday rdf:type WeekendDay").
test(one_of_instances, [ setup(rl_store),
                         true(Xs == [saturday, sunday])
                       ]) :-
    test_find(myself, x, ["?x rdf:type WeekendDay"], Xs).

:- end_tests(owl_rl_class_constructors).


                 /*******************************
                 *            CHAINS            *
                 *******************************/

:- begin_tests(owl_rl_chains).

rl_family :-
    rl_with(["x1 hasParent x2", "x2 hasParent x3", "x2 hasBrother x4",
             "x5 hasParent x2"]).

test(chain, [setup(rl_family)]) :-
    rl_holds("x1 hasGrandparent x3").
test(chain_too_short, [setup(rl_family), fail]) :-
    rl_holds("x2 hasGrandparent x3").
test(chain_super_property, [setup(rl_family)]) :-
    rl_holds("x1 hasAncestor x3").
test(chain_range, [setup(rl_family)]) :-
    rl_holds("x3 rdf:type Elder").
test(chain_range_not_subject, [setup(rl_family), fail]) :-
    rl_holds("x1 rdf:type Elder").
test(chain_inverse, [setup(rl_family)]) :-
    rl_holds("x4 hasNephew x1").
test(chain_inverse_link, [setup(rl_family)]) :-
    rl_holds("x1 hasSibling x5").
test(chain_both_ends_unbound, [ setup(rl_family),
                                true(Pairs == [x1-x3, x5-x3])
                              ]) :-
    findall(S-O, ( oro_holds(myself, S0, oro:hasGrandparent, O0),
                   oro_iri_name(S0, S),
                   oro_iri_name(O0, O)
                 ), Pairs).
test(chain_from_object, [ setup(rl_family),
                          true(Xs == [x1, x5])
                        ]) :-
    test_find(myself, x, ["?x hasUncle x4"], Xs).
test(recursive_chain, [ setup(rl_with(["f1 follows f2", "f2 follows f3",
                                       "f3 follows f4"])),
                        true(Xs == [f2, f3, f4])
                      ]) :-
    test_find(myself, x, ["f1 follows ?x"], Xs).
test(removal, [setup(rl_family), fail]) :-
    oro_remove(myself, ["x2 hasParent x3"]),
    rl_holds("x1 hasGrandparent x3").

:- end_tests(owl_rl_chains).


                 /*******************************
                 *      CYCLES, RUN TIME        *
                 *******************************/

:- begin_tests(owl_rl_cycles).

test(has_value_cycle_holds, [setup(rl_with(["l1 loops loopValue"]))]) :-
    rl_holds("l1 rdf:type Looped").
test(has_value_cycle_not, [setup(rl_with(["l2 loops elsewhere"])), fail]) :-
    rl_holds("l2 rdf:type Looped").
test(has_value_cycle_instances, [ setup(rl_with(["l1 loops loopValue", "l3 rdf:type Looped"])),
                                  true(Xs == [l1, l3])
                                ]) :-
    test_find(myself, x, ["?x loops loopValue"], Xs).
test(mutual_cycle_not, [setup(rl_with(["c1 cycles c2", "c1 rdf:type Marked"])), fail]) :-
    rl_holds("c1 rdf:type CycleA").
test(mutual_cycle_holds, [setup(rl_with(["c1 cycles c2", "c1 rdf:type Marked",
                                         "c2 rdf:type CycleA"]))]) :-
    rl_holds("c1 rdf:type CycleA").
test(mutual_cycle_types, [ setup(rl_with(["c1 cycles c1", "c1 rdf:type Marked"])),
                           true(Classes == ['Marked', 'owl:Thing'])
                         ]) :-
    rl_types(c1, Classes).

:- end_tests(owl_rl_cycles).

:- begin_tests(owl_rl_run_time).

%   Restrictions and lists given as statements, with named nodes (the
%   protocol has no blank nodes).

test(restriction_added, [setup(rl_with(["lamp1 hasColour green"]))]) :-
    \+ rl_holds("lamp1 rdf:type GreenThing"),
    oro_add(myself, ["GreenR rdf:type owl:Restriction", "GreenR owl:onProperty hasColour",
                     "GreenR owl:hasValue green", "GreenThing owl:equivalentClass GreenR"]),
    rl_holds("lamp1 rdf:type GreenThing").
test(intersection_added, [setup(rl_with(["kim rdf:type Woman", "kim rdf:type Pilot"]))]) :-
    \+ rl_holds("kim rdf:type WomanPilot"),
    oro_add(myself, ["WomanPilot owl:intersectionOf L1", "L1 rdf:first Woman",
                     "L1 rdf:rest L2", "L2 rdf:first Pilot", "L2 rdf:rest rdf:nil"]),
    rl_holds("kim rdf:type WomanPilot").
test(removal_of_premise, [setup(rl_with(["ball hasColour red"])), fail]) :-
    oro_remove(myself, ["ball hasColour red"]),
    rl_holds("ball rdf:type RedObject").
test(no_class_expressions, [setup(test_store_testsuite), fail]) :-
    oro_class_definition(myself, _, _).

:- end_tests(owl_rl_run_time).


                 /*******************************
                 *          CONSUMERS           *
                 *******************************/

:- begin_tests(owl_rl_consumers).

rl_consumers :-
    rl_with(["ann rdf:type Woman", "ann hasChild bob", "meg rdf:type Woman",
             "meg hasChild sue", "tom rdf:type Tomato", "ball hasColour red",
             "dan age 30"]).

test(check_conjunction, [setup(rl_consumers)]) :-
    oro_check(myself, ["ann rdf:type Mother", "tom rdf:type RedObject",
                       "?x rdf:type Mother"]).
test(find_join, [ setup(rl_consumers),
                  true(Xs == [ann, meg])
                ]) :-
    test_find(myself, x, ["?x rdf:type Mother", "?x hasChild ?c"], Xs).
test(sparql_select, [ setup(rl_consumers),
                      true(Names == [ball, tom])
                    ]) :-
    oro_query_values(myself, x,
                     "SELECT ?x WHERE { ?x <http://kb.openrobots.org#hasColour> \c
                      <http://kb.openrobots.org#red> }", Values),
    maplist(oro_iri_name, Values, Names0),
    sort(Names0, Names).
test(sparql_ask, [ setup(rl_consumers),
                   true(R == ask(true))
                 ]) :-
    oro_sparql(myself, "ASK { <http://kb.openrobots.org#ann> a \c
                        <http://kb.openrobots.org#Mother> }", R).
test(taxonomy_classes_of, [ setup(rl_consumers),
                            true(Names == ['Mother', 'Parent', 'Person', 'Woman',
                                           'owl:Thing'])
                          ]) :-
    oro_classes_of(myself, oro:ann, Classes),
    maplist(oro_iri_name, Classes, Names0),
    sort(Names0, Names).
test(taxonomy_instances, [ setup(rl_consumers),
                           true(Names == [ann, meg])
                         ]) :-
    oro_instances(myself, oro:'Mother', Xs),
    maplist(oro_iri_name, Xs, Names0),
    sort(Names0, Names).
test(categorization_similarities, [setup(rl_consumers)]) :-
    oro_similarities(myself, oro:ann, oro:meg, Sims),
    rdf_equal(rdf:type, Type),
    rdf_equal(oro:'Mother', Mother),
    memberchk(similar(Type, Mother), Sims).
test(lookup_declared_datatype, [ setup(rl_consumers),
                                 true(Kinds == [datatype_property])
                               ]) :-
    oro_lookup(myself, "isHolder", Matches),
    findall(K, member(_-K, Matches), Kinds).
test(lookup_used_with_literal, [ setup(rl_with(["rintintin hasAge 134"])),
                                 true(Kinds == [datatype_property])
                               ]) :-
    oro_lookup(myself, "hasAge", Matches),
    findall(K, member(_-K, Matches), Kinds).
test(lookup_used_with_resource, [ setup(rl_with(["rintintin hasFriend lassie"])),
                                  true(Kinds == [object_property])
                                ]) :-
    oro_lookup(myself, "hasFriend", Matches),
    findall(K, member(_-K, Matches), Kinds).
test(property_kind_from_super_property, [ setup(rl_with(["ageInYears rdfs:subPropertyOf age"])),
                                          true(Kind == datatype)
                                        ]) :-
    oro_property(myself, oro:ageInYears, Kind).
test(property_kind_from_inverse, [ setup(rl_with(["childOf owl:inverseOf hasParent2"])),
                                   true(Kind == object)
                                 ]) :-
    oro_property(myself, oro:childOf, Kind).
test(event_dependencies_any, [ setup(rl_consumers),
                               true(Deps == [any])
                             ]) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(oro:'Mother', Mother),
    oro_pattern_dependencies(myself, [rdf(_, Type, Mother)], Deps).
test(event_dependencies_plain, [ setup(rl_consumers),
                                 true(Deps \== [any])
                               ]) :-
    rdf_equal(oro:hasChild, HasChild),
    oro_pattern_dependencies(myself, [rdf(_, HasChild, _)], Deps).

:- end_tests(owl_rl_consumers).


                 /*******************************
                 *     THE OPENROBOTS ONTOLOGY  *
                 *******************************/

%   ../shared/ontologies/oro.owl, the reference ontology: loaded alone,
%   it must give the RL inferences its axioms call for.  Skipped with a
%   notice when ../shared is absent.

rl_oro_owl(File) :-
    test_checkout_path('../shared/ontologies/oro.owl', File),
    exists_file(File).

rl_oro_owl_store :-
    rl_oro_owl(File),
    oro_init([commonsense(false), ontologies([File])]).

rl_oro_owl_available :-
    (   rl_oro_owl(_)
    ->  true
    ;   print_message(informational,
                      format("test_owl_rl: ../shared/ontologies/oro.owl is \c
                              absent; its tests are skipped", [])),
        fail
    ).

:- begin_tests(owl_rl_oro_owl, [condition(rl_oro_owl_available)]).

test(has_value_from_sub_class, [setup(rl_oro_owl_store)]) :-
    oro_add(myself, ["bottle1 rdf:type Bottle"]),
    rl_holds("bottle1 hasShape cylinderShape").
test(has_value_literal_through_intersection, [setup(rl_oro_owl_store)]) :-
    oro_add(myself, [rdf(book1, rdf:type, 'https://dbpedia.org/resource/Book')]),
    rl_holds("book1 isMovable true"),
    rl_holds("book1 rdf:type Artifact").
test(intersection_with_has_value, [setup(rl_oro_owl_store)]) :-
    oro_add(myself, ["table1 rdf:type cyc:FurniturePiece", "table1 isHolder true"]),
    rl_holds("table1 rdf:type cyc:Object-SupportingFurniture").
test(intersection_with_has_value_not, [setup(rl_oro_owl_store), fail]) :-
    oro_add(myself, ["table1 rdf:type cyc:FurniturePiece", "table1 isHolder false"]),
    rl_holds("table1 rdf:type cyc:Object-SupportingFurniture").
test(union, [setup(rl_oro_owl_store)]) :-
    oro_add(myself, ["bob rdf:type Human"]),
    rl_holds("bob rdf:type EmbodiedAgent").
test(one_of, [setup(rl_oro_owl_store)]) :-
    rl_holds("sitting rdf:type Posture").
test(disjoint_union_members, [setup(rl_oro_owl_store), fail]) :-
    oro_add(myself, ["bob rdf:type Human", "bob rdf:type Robot"]),
    oro_consistent(myself).
test(property_disjoint, [setup(rl_oro_owl_store), fail]) :-
    oro_add(myself, ["a cyc:near b", "a cyc:farFrom b"]),
    oro_consistent(myself).
test(all_disjoint_classes, [setup(rl_oro_owl_store), fail]) :-
    oro_add(myself, ["c1 rdf:type Bottle", "c1 rdf:type Glass"]),
    oro_consistent(myself).
test(two_shapes_all_different, [setup(rl_oro_owl_store), fail]) :-
    oro_add(myself, ["bottle1 rdf:type Bottle", "bottle1 hasShape boxShape"]),
    oro_consistent(myself).
test(consistent_as_loaded, [setup(rl_oro_owl_store)]) :-
    oro_consistent(myself).

:- end_tests(owl_rl_oro_owl).
