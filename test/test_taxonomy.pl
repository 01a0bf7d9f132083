:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for the eight taxonomy questions (ORO-SPEC §6.4, vectors of
    §13.7) over the test ontology (test/fixtures/testsuite.ttl) with
    `Insect rdfs:subClassOf Animal, Ladybird rdfs:subClassOf Insect`
    added at run time.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_taxonomy.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).

%   The store of §13.7: the test ontology plus insects.

taxonomy_insects :-
    test_store_testsuite,
    oro_add(myself, ["Insect rdfs:subClassOf Animal",
                     "Ladybird rdfs:subClassOf Insect"]).

%   taxonomy(+Pred, +Name, -Names): call oro_<Pred>(myself, IRI, IRIs)
%   on the expanded Name, contract and sort the answer.

taxonomy(Pred, Name, Names) :-
    oro_name_iri(Name, IRI),
    atom_concat(oro_, Pred, Goal),
    call(Goal, myself, IRI, IRIs),
    test_names(IRIs, Names).

%   truth(:Goal, -Truth): Truth is `true` if Goal succeeds, else `false`.

truth(Goal, Truth) :-
    (   call(Goal)
    ->  Truth = true
    ;   Truth = false
    ).

%   taxonomy_labelled(+Pred, +Name, -Pairs): Id-Label pairs, as the
%   ORO protocol answers them (a map of ids to labels).

taxonomy_labelled(Pred, Name, Pairs) :-
    oro_name_iri(Name, IRI),
    atom_concat(oro_, Pred, Goal),
    call(Goal, myself, IRI, IRIs),
    findall(Id-Label, ( member(R, IRIs),
                        oro_iri_name(R, Id),
                        oro_label(myself, R, Label)
                      ), Pairs0),
    sort(Pairs0, Pairs).


                 /*******************************
                 *           SUBCLASSES         *
                 *******************************/

:- begin_tests(subclasses).

test(all_of_animal, [ setup(taxonomy_insects),
                      true(Cs == ['Insect', 'Ladybird', 'Monkey', 'MyAnimals'])
                    ]) :-
    taxonomy(subclasses, 'Animal', Cs).
test(labels_of_animal_subclasses,
     [ setup(taxonomy_insects),
       true(Pairs == ['Insect'-'Insect', 'Ladybird'-'Ladybird',
                      'Monkey'-'Monkey', 'MyAnimals'-'MyAnimals'])
     ]) :-
    taxonomy_labelled(subclasses, 'Animal', Pairs).
test(direct_of_animal, [ setup(taxonomy_insects),
                         true(Cs == ['Insect', 'Monkey', 'MyAnimals'])
                       ]) :-
    taxonomy(direct_subclasses, 'Animal', Cs).
test(all_of_a, [ setup(taxonomy_insects),
                 true(Cs == ['B', 'C', 'D', 'E', 'F', 'I', 'J', 'K'])
               ]) :-
    taxonomy(subclasses, 'A', Cs).
test(direct_of_a, [ setup(taxonomy_insects),
                    true(Cs == ['B', 'D'])
                  ]) :-
    taxonomy(direct_subclasses, 'A', Cs).
test(direct_of_d, [ setup(taxonomy_insects),
                    true(Cs == ['E', 'I', 'K'])
                  ]) :-
    taxonomy(direct_subclasses, 'D', Cs).
test(leaf, [ setup(taxonomy_insects),
             true(Cs == [])
           ]) :-
    taxonomy(subclasses, 'Ladybird', Cs).
test(direct_leaf, [ setup(taxonomy_insects),
                    true(Cs == [])
                  ]) :-
    taxonomy(direct_subclasses, 'Monkey', Cs).
test(of_thing_has_all, [ setup(taxonomy_insects),
                         true(Missing == [])
                       ]) :-
    taxonomy(subclasses, 'owl:Thing', Cs),
    subtract(['A', 'Animal', 'Insect', 'Ladybird', 'Monkey', 'Plant'], Cs,
             Missing).
test(equivalent_same_level, [ setup(taxonomy_insects),
                              true(Cs == ['Ape', 'Insect', 'Monkey', 'MyAnimals'])
                            ]) :-
    oro_add(myself, ["Ape owl:equivalentClass Monkey"]),
    taxonomy(direct_subclasses, 'Animal', Cs).
test(type_only_class_under_thing,    % a class only used as a type
     [ setup(taxonomy_insects),
       true(In-Direct == true-true)
     ]) :-
    oro_add(myself, ["x1 rdf:type Gadget"]),
    taxonomy(subclasses, 'owl:Thing', Cs),
    taxonomy(direct_subclasses, 'owl:Thing', Ds),
    truth(memberchk('Gadget', Cs), In),
    truth(memberchk('Gadget', Ds), Direct).
test(type_only_class_found_as_sub_class,
     [ setup(taxonomy_insects),
       true(In-Self == true-['Gadget'])
     ]) :-
    oro_add(myself, ["x1 rdf:type Gadget"]),
    oro_find(myself, c, ["?c rdfs:subClassOf owl:Thing"], Cs0),
    test_names(Cs0, Cs),
    truth(memberchk('Gadget', Cs), In),
    oro_find(myself, c, ["?c rdfs:subClassOf Gadget"], Self0),
    test_names(Self0, Self).
test(not_a_class, [ setup(taxonomy_insects),
                    error(existence_error(class, _))
                  ]) :-
    taxonomy(subclasses, baboon, _).
test(unknown, [ setup(taxonomy_insects),
                error(existence_error(class, _))
              ]) :-
    taxonomy(direct_subclasses, 'Unicorn', _).

:- end_tests(subclasses).


                 /*******************************
                 *          SUPERCLASSES        *
                 *******************************/

:- begin_tests(superclasses).

test(all_of_ladybird, [ setup(taxonomy_insects),
                        true(Cs == ['Animal', 'Insect', 'owl:Thing'])
                      ]) :-
    taxonomy(superclasses, 'Ladybird', Cs).
test(direct_of_ladybird, [ setup(taxonomy_insects),
                           true(Cs == ['Insect'])
                         ]) :-
    taxonomy(direct_superclasses, 'Ladybird', Cs).
test(direct_of_ladybird_labelled, [ setup(taxonomy_insects),
                                    true(Pairs == ['Insect'-'Insect'])
                                  ]) :-
    taxonomy_labelled(direct_superclasses, 'Ladybird', Pairs).
test(all_of_f, [ setup(taxonomy_insects),
                 true(Cs == ['A', 'B', 'C', 'D', 'E', 'owl:Thing'])
               ]) :-
    taxonomy(superclasses, 'F', Cs).
test(direct_two_parents, [ setup(taxonomy_insects),
                           true(Cs == ['C', 'D'])
                         ]) :-
    taxonomy(direct_superclasses, 'E', Cs).
test(direct_two_parents_j, [ setup(taxonomy_insects),
                             true(Cs == ['B', 'I'])
                           ]) :-
    taxonomy(direct_superclasses, 'J', Cs).
test(direct_of_top, [ setup(taxonomy_insects),
                      true(Cs == ['owl:Thing'])
                    ]) :-
    taxonomy(direct_superclasses, 'A', Cs).
test(direct_of_individual, [ setup(taxonomy_insects),
                             error(existence_error(class, _))
                           ]) :-
    taxonomy(direct_superclasses, baboon, _).
test(of_individual, [ setup(taxonomy_insects),
                      error(existence_error(class, _))
                    ]) :-
    taxonomy(superclasses, gorilla, _).

:- end_tests(superclasses).


                 /*******************************
                 *           INSTANCES          *
                 *******************************/

:- begin_tests(instances).

test(of_animal, [ setup(taxonomy_insects),
                  true(Xs == [baboon, cow, gorilla])
                ]) :-
    taxonomy(instances, 'Animal', Xs).
test(of_animal_labelled, [ setup(taxonomy_insects),
                           true(Pairs == [baboon-'baboon monkey', cow-cow,
                                          gorilla-gorilla])
                         ]) :-
    taxonomy_labelled(instances, 'Animal', Pairs).
test(direct_of_plant, [ setup(taxonomy_insects),
                        true(Xs == [apple, banana_tree, grass])
                      ]) :-
    taxonomy(direct_instances, 'Plant', Xs).
test(direct_of_animal, [ setup(taxonomy_insects),
                         true(Xs == [cow])
                       ]) :-
    taxonomy(direct_instances, 'Animal', Xs).
test(of_a, [ setup(taxonomy_insects),
             true(Xs == [e, f, j, k])
           ]) :-
    taxonomy(instances, 'A', Xs).
test(direct_of_a, [ setup(taxonomy_insects),
                    true(Xs == [])
                  ]) :-
    taxonomy(direct_instances, 'A', Xs).
test(direct_of_e, [ setup(taxonomy_insects),
                    true(Xs == [e])
                  ]) :-
    taxonomy(direct_instances, 'E', Xs).
test(added_instance, [ setup(taxonomy_insects),
                       true(Xs-Ds == [baboon, cow, gorilla, ladybug]-[ladybug])
                     ]) :-
    oro_add(myself, ["ladybug rdf:type Ladybird"]),
    taxonomy(instances, 'Animal', Xs),
    taxonomy(direct_instances, 'Ladybird', Ds).
test(empty_class, [ setup(taxonomy_insects),
                    true(Xs == [])
                  ]) :-
    taxonomy(instances, 'Insect', Xs).
test(of_individual, [ setup(taxonomy_insects),
                      error(existence_error(class, _))
                    ]) :-
    taxonomy(instances, baboon, _).
test(direct_of_individual, [ setup(taxonomy_insects),
                             error(existence_error(class, _))
                           ]) :-
    taxonomy(direct_instances, baboon, _).

:- end_tests(instances).


                 /*******************************
                 *       CLASSES OF INDIVIDUAL  *
                 *******************************/

:- begin_tests(classes_of).

test(direct_of_baboon, [ setup(taxonomy_insects),
                         true(Cs == ['Monkey', 'MyAnimals'])
                       ]) :-
    taxonomy(direct_classes_of, baboon, Cs).
test(direct_of_baboon_labelled,
     [ setup(taxonomy_insects),
       true(Pairs == ['Monkey'-'Monkey', 'MyAnimals'-'MyAnimals'])
     ]) :-
    taxonomy_labelled(direct_classes_of, baboon, Pairs).
test(all_of_baboon, [ setup(taxonomy_insects),
                      true(Cs == ['Animal', 'Monkey', 'MyAnimals', 'owl:Thing'])
                    ]) :-
    taxonomy(classes_of, baboon, Cs).
test(inferred_by_range, [ setup(taxonomy_insects),
                          true(Cs == ['Plant'])
                        ]) :-
    taxonomy(direct_classes_of, apple, Cs).
test(direct_of_f, [ setup(taxonomy_insects),
                    true(Cs == ['F'])
                  ]) :-
    taxonomy(direct_classes_of, f, Cs).
test(all_of_j, [ setup(taxonomy_insects),
                 true(Cs == ['A', 'B', 'D', 'I', 'J', 'owl:Thing'])
               ]) :-
    taxonomy(classes_of, j, Cs).
test(added_individual, [ setup(taxonomy_insects),
                         true(Cs == ['Animal', 'Insect', 'Ladybird', 'owl:Thing'])
                       ]) :-
    oro_add(myself, ["ladybug rdf:type Ladybird"]),
    taxonomy(classes_of, ladybug, Cs).
test(meta_class, [ setup(taxonomy_insects),
                   true(Cs == [])
                 ]) :-
    taxonomy(classes_of, 'owl:Class', Cs).
test(of_class, [ setup(taxonomy_insects),
                 error(existence_error(individual, _))
               ]) :-
    taxonomy(classes_of, 'Monkey', _).
test(direct_of_class, [ setup(taxonomy_insects),
                        error(existence_error(individual, _))
                      ]) :-
    taxonomy(direct_classes_of, 'Monkey', _).
test(unknown, [ setup(taxonomy_insects),
                error(existence_error(resource, _))
              ]) :-
    taxonomy(classes_of, i_d_ont_exist, _).

:- end_tests(classes_of).


                 /*******************************
                 *     THE BUNDLED ONTOLOGY     *
                 *******************************/

%   The common-sense ontology never names owl:Thing, which the
%   taxonomy gives as the top class: its label must not need a triple.
%   The ontology's header (`<http://kb.openrobots.org> a owl:Ontology`,
%   with annotations) is no individual.

:- begin_tests(commonsense_taxonomy, [setup(oro_init([]))]).

test(superclasses_labelled,
     [ true(Pairs == ['Agent'-agent, 'EmbodiedAgent'-'embodied agent',
                      'owl:Thing'-'Thing'])
     ]) :-
    taxonomy_labelled(superclasses, 'Robot', Pairs).
test(classes_of_labelled, [true(memberchk('owl:Thing'-'Thing', Pairs))]) :-
    oro_add(myself, ["cup1 rdf:type Cup"]),
    taxonomy_labelled(classes_of, cup1, Pairs).
test(label_of_thing, true(Label == 'Thing')) :-
    oro_label(myself, owl:'Thing', Label).
test(header_no_individual, fail) :-
    oro_individual(myself, 'http://kb.openrobots.org').
test(header_no_instance_of_thing, true(Header == [])) :-
    oro_instances(myself, owl:'Thing', Xs),
    include(==('http://kb.openrobots.org'), Xs, Header).
test(header_not_looked_up, true(Matches == [])) :-
    oro_lookup(myself, "kb.openrobots.org", Matches).

:- end_tests(commonsense_taxonomy).


                 /*******************************
                 *            NAMES             *
                 *******************************/

/*  Classes and individuals are named as in statements: short, prefixed
    (a Prefix:Local term at run time, which rdf_meta does not expand)
    or full IRIs.  A short individual was unknown to oro_classes_of/3
    (existence_error(resource, fork1)), a prefixed term a type error.
*/

:- begin_tests(taxonomy_names, [setup(taxonomy_insects)]).

%   taxonomy_forms(+Local, -Forms): the three names of Local.

taxonomy_forms(Local, [Local, oro:Local, IRI]) :-
    oro_name_iri(Local, IRI).

%   taxonomy_same(+Pred, +Local): oro_<Pred> answers the same for each
%   name of Local.

taxonomy_same(Pred, Local) :-
    taxonomy_forms(Local, Forms),
    atom_concat(oro_, Pred, Goal),
    findall(Answer, ( member(Name, Forms),
                      call(Goal, myself, Name, Answer)
                    ), [A, B, C]),
    A == B,
    B == C.

test(superclasses) :-
    taxonomy_same(superclasses, 'Ladybird').
test(direct_superclasses) :-
    taxonomy_same(direct_superclasses, 'Ladybird').
test(subclasses) :-
    taxonomy_same(subclasses, 'Animal').
test(direct_subclasses) :-
    taxonomy_same(direct_subclasses, 'Animal').
test(instances) :-
    taxonomy_same(instances, 'Monkey').
test(direct_instances) :-
    taxonomy_same(direct_instances, 'Monkey').
test(classes_of, true(Names == ['Animal', 'Monkey', 'MyAnimals',
                                'owl:Thing'])) :-
    taxonomy_same(classes_of, gorilla),
    oro_classes_of(myself, gorilla, Classes),
    test_names(Classes, Names).
test(direct_classes_of) :-
    taxonomy_same(direct_classes_of, gorilla).
test(unbound, error(instantiation_error)) :-
    oro_instances(myself, _, _).
test(not_a_name, error(type_error(oro_resource, 3))) :-
    oro_classes_of(myself, 3, _).

:- end_tests(taxonomy_names).
