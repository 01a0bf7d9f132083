:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for labels, lookup and descriptions of resources (ORO-SPEC
    §6.3, vectors of §13.6 and §13.8): oro_lookup/3, oro_label/3,4,
    oro_resource_kind/3, oro_exists/2, oro_infos/3 and
    oro_resource_details/4, over the test ontology
    (test/fixtures/testsuite.ttl).

    Run: cd /work/main && swipl -g run_tests -t halt test/test_lookup.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).

lookup_testsuite :-
    test_store_testsuite.

%   The store of §13.6: a label for gorilla and a human.

lookup_kingkong :-
    lookup_testsuite,
    oro_add(myself, ["gorilla rdfs:label \"king kong\"",
                     "iddebile rdf:type Human"]).

%   The store of the typed lookups of §13.6.

lookup_rintintin :-
    lookup_testsuite,
    oro_add(myself, ["rintintin rdf:type Dog", "lassie rdf:type Cat",
                     "rintintin sees lassie", "rintintin hasAge 134"]).

%   lookup(+Text, -Matches): oro_lookup/3 on the robot model, as sorted
%   Id-Kind pairs with contracted ids.

lookup(Text, Matches) :-
    oro_lookup(myself, Text, Matches0),
    findall(Id-Kind, ( member(R-Kind, Matches0),
                       oro_iri_name(R, Id)
                     ), Matches1),
    sort(Matches1, Matches).

%   lookup_kind(+Text, +Kind, -Ids): the typed lookup of ORO,
%   `lookup(text, type)`.

lookup_kind(Text, Kind, Ids) :-
    lookup(Text, Matches),
    findall(Id, member(Id-Kind, Matches), Ids).

%   lookup_kinds(+Name, -Kinds): the kinds of a resource.

lookup_kinds(Name, Kinds) :-
    oro_name_iri(Name, R),
    findall(K, oro_resource_kind(myself, R, K), Kinds0),
    sort(Kinds0, Kinds).

%   lookup_infos(+Name, -Texts): oro_infos/3 as "s p o" strings with
%   contracted names and literal lexical forms.

lookup_infos(Name, Texts) :-
    oro_name_iri(Name, R),
    oro_infos(myself, R, Triples),
    maplist(lookup_triple_text, Triples, Texts0),
    sort(Texts0, Texts).

lookup_triple_text(rdf(S, P, O), Text) :-
    maplist(oro_term_text, [S, P, O], [ST, PT, OT]),
    format(string(Text), "~w ~w ~w", [ST, PT, OT]).


                 /*******************************
                 *            LOOKUP            *
                 *******************************/

:- begin_tests(lookup).

test(no_match, [ setup(lookup_kingkong),
                 true(Ms == [])
               ]) :-
    lookup('princess Daisy', Ms).
test(french_label_any_case, [ setup(lookup_kingkong),
                              true(Ms == [baboon-instance])
                            ]) :-
    lookup('BabouIn', Ms).
test(english_label, [ setup(lookup_kingkong),
                      true(Ms == [baboon-instance])
                    ]) :-
    lookup('Baboon monkey', Ms).
test(string_text, [ setup(lookup_kingkong),
                    true(Ms == [baboon-instance])
                  ]) :-
    lookup("baboon monkey", Ms).
test(individual_by_name, [ setup(lookup_kingkong),
                           true(Ms == [baboon-instance])
                         ]) :-
    lookup(baboon, Ms).
test(added_label, [ setup(lookup_kingkong),
                    true(Ms == [gorilla-instance])
                  ]) :-
    lookup('king kong', Ms).
test(labelled_individual_by_name, [ setup(lookup_kingkong),
                                    true(Ms == [gorilla-instance])
                                  ]) :-
    lookup('GORILLA', Ms).
test(added_individual, [ setup(lookup_kingkong),
                         true(Ms == [iddebile-instance])
                       ]) :-
    lookup(iddebile, Ms).
test(class, [ setup(lookup_kingkong),
              true(Ms == ['Monkey'-class])
            ]) :-
    lookup('Monkey', Ms).
test(class_any_case, [ setup(lookup_kingkong),
                       true(Ms == ['Monkey'-class])
                     ]) :-
    lookup(monkey, Ms).
test(unlabelled_class_by_name, [ setup(lookup_kingkong),
                                 true(Ms == ['Plant'-class])
                               ]) :-
    lookup(plant, Ms).
test(no_substring, [ setup(lookup_kingkong),
                     true(Ms == [])
                   ]) :-
    lookup(king, Ms).
test(class_and_instance, [ setup(lookup_kingkong),
                           true(Ms == ['KingKong'-class, gorilla-instance])
                         ]) :-
    oro_add(myself, ["KingKong rdfs:subClassOf Monkey",
                     "KingKong rdfs:label \"king kong\""]),
    lookup('king kong', Ms).
test(labelled_class_not_by_name, [ setup(lookup_kingkong),
                                   true(Ms == [])
                                 ]) :-
    oro_add(myself, ["KingKong rdfs:subClassOf Monkey",
                     "KingKong rdfs:label \"king kong\""]),
    lookup('KingKong', Ms).
test(cleared, [ setup(lookup_kingkong),
                true(Ms == [])
              ]) :-
    Stmts = ["KingKong rdfs:subClassOf Monkey",
             "KingKong rdfs:label \"king kong\""],
    oro_add(myself, Stmts),
    oro_clear(myself, Stmts),
    oro_clear(myself, ["gorilla ?a ?b"]),
    lookup('king kong', Ms).
test(object_property, [ setup(lookup_testsuite),
                        true(Ms == [climbsOn-object_property])
                      ]) :-
    lookup(climbson, Ms).
test(datatype_property, [ setup(lookup_testsuite),
                          true(Ms == [age-datatype_property])
                        ]) :-
    lookup(age, Ms).

:- end_tests(lookup).


                 /*******************************
                 *          NAME INDEX          *
                 *******************************/

%   Lookup by name goes through the store's index of local names
%   (oro_named/2): it must follow adds, removes (the name leaves the
%   index with its last triple), memory forgetting's writes, rolled
%   back writes and resets.

index_has(Lower, Has) :-
    (   oro_store:oro_named(Lower, _)
    ->  Has = true
    ;   Has = false
    ).

:- begin_tests(lookup_name_index, [setup(lookup_testsuite)]).

test(follows_add_and_remove,
     [ true(Got == [['Zebulon'-instance], true, [], false, ['Zebulon'-instance]]) ]) :-
    oro_add(myself, ["Zebulon rdf:type Animal"]),
    lookup(zebulon, M1),
    index_has(zebulon, H1),
    oro_remove(myself, ["Zebulon rdf:type Animal"]),
    lookup(zebulon, M2),
    index_has(zebulon, H2),
    oro_add(myself, ["Zebulon rdf:type Animal"]),
    lookup(zebulon, M3),
    Got = [M1, H1, M2, H2, M3].
test(kept_while_used, [true(M == [zoe-instance])]) :-
    oro_add(myself, ["zoe rdf:type Animal", "baboon sees zoe"]),
    oro_remove(myself, ["zoe rdf:type Animal"]),
    lookup(zoe, M).
test(kept_when_the_remove_is_rolled_back, [true(M == [zed-instance])]) :-
    oro_add(myself, ["zed rdf:type Animal"]),
    catch(oro_store:oro_store_write(test_rollback,
                                    ( oro_remove(myself, ["zed rdf:type Animal"]),
                                      throw(rolled_back)
                                    )),
          rolled_back, true),
    lookup(zed, M).
test(ontology_names_after_reset, [true(M == ['Monkey'-class])]) :-
    oro_add(myself, ["zorro rdf:type Animal"]),
    oro_reset,
    lookup(monkey, M).

:- end_tests(lookup_name_index).


                 /*******************************
                 *     LOOKUP BY KIND (§13.6)   *
                 *******************************/

:- begin_tests(lookup_kind).

test(instance, [ setup(lookup_rintintin),
                 true(Ids == [rintintin])
               ]) :-
    lookup_kind(rintintin, instance, Ids).
test(instance_not_class, [ setup(lookup_rintintin),
                           true(Ids == [])
                         ]) :-
    lookup_kind(rintintin, class, Ids).
test(class, [ setup(lookup_rintintin),
              true(Ids == ['Dog'])
            ]) :-
    lookup_kind(dog, class, Ids).
test(class_not_instance, [ setup(lookup_rintintin),
                           true(Ids == [])
                         ]) :-
    lookup_kind(dog, instance, Ids).
test(object_property, [ setup(lookup_rintintin),
                        true(Ids == [sees])
                      ]) :-
    lookup_kind(sees, object_property, Ids).
test(object_not_datatype, [ setup(lookup_rintintin),
                            true(Ids == [])
                          ]) :-
    lookup_kind(sees, datatype_property, Ids).
test(datatype_by_usage, [ setup(lookup_rintintin),
                          true(Ids == [hasAge])
                        ]) :-
    lookup_kind(hasage, datatype_property, Ids).
test(kind_hasage, [ setup(lookup_rintintin),
                    true(Kinds == [datatype_property])
                  ]) :-
    lookup_kinds(hasAge, Kinds).
test(kind_sees, [ setup(lookup_rintintin),
                  true(Kinds == [object_property])
                ]) :-
    lookup_kinds(sees, Kinds).
test(kind_dog, [ setup(lookup_rintintin),
                 true(Kinds == [class])
               ]) :-
    lookup_kinds('Dog', Kinds).
test(kind_rintintin, [ setup(lookup_rintintin),
                       true(Kinds == [instance])
                     ]) :-
    lookup_kinds(rintintin, Kinds).
test(kind_declared_datatype, [ setup(lookup_rintintin),
                               true(Kinds == [datatype_property])
                             ]) :-
    lookup_kinds(weight, Kinds).

:- end_tests(lookup_kind).


                 /*******************************
                 *            LABELS            *
                 *******************************/

:- begin_tests(label).

test(english_label, [ setup(lookup_testsuite),
                      true(L == 'baboon monkey')
                    ]) :-
    oro_label(myself, oro:baboon, L).
test(french_label, [ setup(lookup_testsuite),
                     true(L == babouin)
                   ]) :-
    oro_label(myself, oro:baboon, fr, L).
test(french_label_string, [ setup(lookup_testsuite),          % was English
                            true(L == babouin)
                          ]) :-
    oro_label(myself, oro:baboon, "fr", L).
test(language_case, [ setup(lookup_testsuite),
                      true(Ls == [babouin, tasse])
                    ]) :-
    oro_add(myself, ["cup1 rdfs:label \"tasse\"@FR",
                     "cup1 rdfs:label \"cup\"@en"]),
    oro_label(myself, oro:baboon, 'FR', L1),
    oro_label(myself, oro:cup1, fr, L2),
    Ls = [L1, L2].
test(details_language, [ setup(lookup_testsuite),
                         true(Name == babouin)
                       ]) :-
    oro_resource_details(myself, oro:baboon, "FR", Details),
    get_dict(name, Details, Name).
test(unbound_language, [ setup(lookup_testsuite),
                         error(instantiation_error)
                       ]) :-
    oro_label(myself, oro:baboon, _, _).
test(other_language_falls_back, [ setup(lookup_testsuite),
                                  true(L == 'baboon monkey')
                                ]) :-
    oro_label(myself, oro:baboon, de, L).
test(no_label_local_name, [ setup(lookup_testsuite),
                            true(L == gorilla)
                          ]) :-
    oro_label(myself, oro:gorilla, L).
test(class_label, [ setup(lookup_testsuite),
                    true(L == 'Monkey')
                  ]) :-
    oro_label(myself, oro:'Monkey', L).
test(added_label, [ setup(lookup_kingkong),
                    true(L == 'king kong')
                  ]) :-
    oro_label(myself, oro:gorilla, L).
test(prefixed_resource, [ setup(lookup_testsuite),
                          true(L == 'Thing')
                        ]) :-
    oro_label(myself, owl:'Thing', L).
test(language_any_case, [ setup(lookup_testsuite),
                          true(L == babouin)
                        ]) :-
    oro_label(myself, oro:baboon, 'FR', L).
test(regional_label_for_language,   % "cup"@en-GB, not "Tasse"@de, for en
     [ setup(lookup_testsuite),
       true(L-LR == cup-cup)
     ]) :-
    oro_add(myself, ["cup1 rdfs:label \"Tasse\"@de",
                     "cup1 rdfs:label \"cup\"@en-GB"]),
    oro_label(myself, oro:cup1, L),
    oro_label(myself, oro:cup1, 'en-US', LR).
test(exact_tag_before_region, [ setup(lookup_testsuite),
                                true(L == color)
                              ]) :-
    oro_add(myself, ["cup1 rdfs:label \"color\"@en-US",
                     "cup1 rdfs:label \"colour\"@en-GB"]),
    oro_label(myself, oro:cup1, 'EN-us', L).
test(unknown, [ setup(lookup_testsuite),
                error(existence_error(resource, _))
              ]) :-
    oro_label(myself, oro:i_d_ont_exist, _).
test(exists, [setup(lookup_testsuite)]) :-
    oro_exists(myself, oro:baboon).
test(exists_as_object_only, [setup(lookup_testsuite)]) :-
    oro_exists(myself, oro:banana_tree).
test(does_not_exist, [setup(lookup_testsuite), fail]) :-
    oro_exists(myself, oro:i_d_ont_exist).

:- end_tests(label).


                 /*******************************
                 *             INFOS            *
                 *******************************/

:- begin_tests(infos).

test(baboon, [ setup(lookup_testsuite),
               true(Missing == [])
             ]) :-
    lookup_infos(baboon, Texts),
    subtract(["baboon rdf:type Animal", "baboon isFemale true",
              "baboon rdf:type Monkey", "baboon climbsOn banana_tree",
              "baboon age 35", "baboon isOn banana_tree",
              "baboon isAt banana_tree", "baboon rdfs:label baboon monkey"],
             Texts, Missing).
test(subject_only, [ setup(lookup_testsuite),
                     true(Found == [])
                   ]) :-
    lookup_infos(cow, Texts),
    include(==("grass isUnder cow"), Texts, Found).
test(inverse_included, [ setup(lookup_testsuite),
                         true(Missing == [])
                       ]) :-
    lookup_infos(cow, Texts),
    subtract(["cow isOn grass", "cow eats grass"], Texts, Missing).
test(triples_about_resource, [ setup(lookup_testsuite),
                               true(Others == [])
                             ]) :-
    oro_name_iri(baboon, Baboon),
    oro_infos(myself, Baboon, Triples),
    findall(S, ( member(rdf(S, _, _), Triples), S \== Baboon ), Others).
test(unknown, [ setup(lookup_testsuite),
                error(existence_error(resource, _))
              ]) :-
    oro_infos(myself, oro:i_d_ont_exist, _).

:- end_tests(infos).


                 /*******************************
                 *        RESOURCE DETAILS      *
                 *******************************/

:- begin_tests(resource_details).

test(class_header, [ setup(lookup_testsuite),
                     true(Name-Type-Same == 'Monkey'-class-[])
                   ]) :-
    oro_resource_details(myself, oro:'Monkey', en, D),
    Name = D.name,
    Type = D.type,
    Same = D.same_as.
test(class_attributes,
     [ setup(lookup_testsuite),
       true(As == [ attribute('Parents', superClasses,
                              [value('Animal', 'Animal')]),
                    attribute('Children', subClasses, []),
                    attribute('Instances', instances,
                              [ value('baboon monkey', baboon),
                                value(gorilla, gorilla)
                              ])
                  ])
     ]) :-
    oro_resource_details(myself, oro:'Monkey', en, D),
    maplist(lookup_contract_attribute, D.attributes, As).
test(class_same_as, [ setup(lookup_testsuite),
                      true(Same == [Ape])
                    ]) :-
    oro_add(myself, ["Ape owl:equivalentClass Monkey"]),
    oro_name_iri('Ape', Ape),
    oro_resource_details(myself, oro:'Monkey', en, D),
    Same = D.same_as.
test(instance_header, [ setup(lookup_testsuite),
                        true(Name-Type == 'baboon monkey'-instance)
                      ]) :-
    oro_resource_details(myself, oro:baboon, en, D),
    Name = D.name,
    Type = D.type.
test(instance_label_language, [ setup(lookup_testsuite),
                                true(Name == babouin)
                              ]) :-
    oro_resource_details(myself, oro:baboon, fr, D),
    Name = D.name.
test(instance_classes_first,
     [ setup(lookup_testsuite),
       true(First == attribute('Classes', classes,
                               [ value('Monkey', 'Monkey'),
                                 value('MyAnimals', 'MyAnimals')
                               ]))
     ]) :-
    oro_resource_details(myself, oro:baboon, en, D),
    D.attributes = [First0|_],
    lookup_contract_attribute(First0, First).
test(instance_properties,
     [ setup(lookup_testsuite),
       true(Missing == [])
     ]) :-
    oro_resource_details(myself, oro:baboon, en, D),
    maplist(lookup_contract_attribute, D.attributes, As),
    subtract([ attribute(age, properties, [value('35', literal)]),
               attribute(climbsOn, properties,
                         [value(banana_tree, banana_tree)]),
               attribute(isFemale, properties, [value(true, literal)])
             ], As, Missing).
test(instance_hidden_properties,
     [ setup(lookup_testsuite),
       true(Hidden == [])
     ]) :-
    oro_resource_details(myself, oro:baboon, en, D),
    findall(N, ( member(attribute(N, properties, _), D.attributes),
                 memberchk(N, [type, sameAs, label, differentFrom])
               ), Hidden).
test(instance_same_as, [ setup(lookup_testsuite),
                         true(Same == [KK])
                       ]) :-
    oro_add(myself, ["kingkong owl:sameAs gorilla"]),
    oro_name_iri(kingkong, KK),
    oro_resource_details(myself, oro:gorilla, en, D),
    Same = D.same_as.
test(object_property, [ setup(lookup_testsuite),
                        true(Type-As == object_property-[])
                      ]) :-
    oro_resource_details(myself, oro:eats, en, D),
    Type = D.type,
    As = D.attributes.
test(class_and_individual,          % punning: described as the class
     [ setup(lookup_testsuite),
       true(Type-Names == class-['Parents', 'Children', 'Instances'])
     ]) :-
    oro_add(myself, ["Dog rdfs:subClassOf Animal", "Dog rdf:type Species",
                     "rex rdf:type Dog"]),
    oro_resource_details(myself, oro:'Dog', en, D),
    Type = D.type,
    findall(N, member(attribute(N, _, _), D.attributes), Names).
test(unknown, [ setup(lookup_testsuite),
                error(existence_error(resource, _))
              ]) :-
    oro_resource_details(myself, oro:i_d_ont_exist, en, _).

%   lookup_contract_attribute(+Attribute, -Contracted): the ids of the
%   values of an attribute contracted, for readable expectations.

lookup_contract_attribute(attribute(Name, Id, Values0),
                          attribute(Name, Id, Values)) :-
    maplist(lookup_contract_value, Values0, Values).

lookup_contract_value(value(Label, literal), value(Label, literal)) :-
    !.
lookup_contract_value(value(Label, R), value(Label, Id)) :-
    oro_iri_name(R, Id).

:- end_tests(resource_details).


                 /*******************************
                 *            NAMES             *
                 *******************************/

/*  Resources are named as in statements: short, prefixed (a
    Prefix:Local term at run time, which rdf_meta does not expand) or
    full IRIs.  oro_exists(myself, gorilla) failed, and oro_label/3,
    oro_infos/3 and oro_resource_details/4 raised
    existence_error(resource, gorilla).
*/

:- begin_tests(lookup_names, [setup(lookup_kingkong)]).

%   lookup_same(+Goal, +Local): call(Goal, Name, Answer) answers the
%   same for each name of Local: short, prefixed and full (variants: a
%   dict's tag is a fresh variable).

lookup_same(Goal, Local) :-
    oro_name_iri(Local, IRI),
    findall(Answer, ( member(Name, [Local, oro:Local, IRI]),
                      call(Goal, Name, Answer)
                    ), [A, B, C]),
    A =@= B,
    B =@= C.

lookup_exists(Name, true) :-
    oro_exists(myself, Name).

lookup_label(Name, Label) :-
    oro_label(myself, Name, Label).

lookup_label_fr(Name, Label) :-
    oro_label(myself, Name, fr, Label).

lookup_resource_kinds(Name, Kinds) :-
    findall(Kind, oro_resource_kind(myself, Name, Kind), Kinds).

lookup_resource_infos(Name, Triples) :-
    oro_infos(myself, Name, Triples).

lookup_details(Name, Details) :-
    oro_resource_details(myself, Name, en, Details).

test(exists) :-
    lookup_same(lookup_exists, gorilla).
test(label, true(Label == 'king kong')) :-
    lookup_same(lookup_label, gorilla),
    oro_label(myself, gorilla, Label).
test(label_lang) :-
    lookup_same(lookup_label_fr, gorilla).
test(resource_kind, true(Kinds == [instance])) :-
    lookup_same(lookup_resource_kinds, gorilla),
    lookup_resource_kinds(gorilla, Kinds).
test(infos) :-
    lookup_same(lookup_resource_infos, gorilla).
test(details) :-
    lookup_same(lookup_details, gorilla).
test(class_details) :-
    lookup_same(lookup_details, 'Monkey').
test(unknown_short, error(existence_error(resource, IRI))) :-
    oro_name_iri(i_d_ont_exist, IRI),
    oro_infos(myself, i_d_ont_exist, _).
test(unbound, error(instantiation_error)) :-
    oro_label(myself, _, _).

:- end_tests(lookup_names).
