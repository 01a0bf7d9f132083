:- module(oro_categorize,
          [ oro_similarities/4,         % +Model, +A, +B, -Similarities
            oro_differences/4,          % +Model, +A, +B, -Differences
            oro_common_ancestors/4,     % +Model, +A, +B, -Classes
            oro_discriminate/4,         % +Model, +Individuals, -Total, -Best
            oro_discriminants/3,        % +Model, +Individuals, -Discriminants
            oro_partition/4             % +Model, +Individuals, +Property, -Partition
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(error)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/questions/oro_taxonomy)).
:- use_module(library(oro/questions/oro_lookup)).

/** <module> Categorization: what tells individuals apart

When a human says "give me the thing!", the robot must find what tells
the candidates apart.  This module answers ORO's three concept
comparison questions (ORO-SPEC §6.5, algorithms of §10) over the
inference closure of a model, with terms a planner can use directly:

  - oro_similarities/4: what two individuals have in common, as
    `similar(Property, Value)` terms (`similar(rdf:type, oro:'Animal')`,
    `similar(oro:eats, oro:grass)`);
  - oro_differences/4: what tells two individuals apart, as groups of
    rdf(S, P, O) triples, one group per point of difference;
  - oro_discriminate/4: the properties that best split a set of
    individuals, and whether they split it completely;
  - oro_discriminants/3: the same as `discriminant(Property, Partition)`
    terms, where Partition groups the individuals by their values, so a
    planner can ask "which colour?" and keep the group the answer
    names; oro_partition/4 gives the partition by any property.

The seed's example, over the test ontology: which thing does the
human want?

    ?- oro_add(myself, ["plant1 rdf:type Plant", "plant1 hasColor green",
                        "animal1 rdf:type Animal", "animal1 eats banana",
                        "animal2 rdf:type Animal", "animal2 eats grass",
                        "animal2 hasColor blue",
                        "animal3 rdf:type Animal", "animal3 hasColor red"]),
       oro_discriminants(myself, [plant1, animal1, animal2, animal3], Ds).
    Ds = [discriminant(oro:hasColor, [ []-[oro:animal1],
                                       [oro:blue]-[oro:animal2],
                                       [oro:green]-[oro:plant1],
                                       [oro:red]-[oro:animal3] ])].

The colour is the best question; it does not single out every
candidate (animal1 has no known colour), so oro_discriminate/4 answers
`Total = []`, `Best = [oro:hasColor]`.

The algorithms are those of oro-server 0.8.2 (§10), made deterministic
(ORO-SPEC §16):

  - Where 0.8.2 takes "one direct type" of an individual, the *set* of
    its direct named types is used, as a single value: two individuals
    with the same direct types share it.
  - In discriminate, the values an individual has for a property count
    as one value, its value *set*, exactly as the direct types do.  On
    single-valued properties (all of §13.9) this is the union count of
    §10.5; on multi-valued ones it keeps the claims true: a total
    discriminant gives every individual its own value set, a best one
    sets at least two individuals apart.  A property left without any
    value by the super-property pruning (§10.5 step 2) says nothing and
    is dropped.
  - Discriminate compares, as §10.5 does, the values of a property that
    no sub-property of it carries as well (so `climbsOn` wins over
    `isOn` and `isAt`).  The partitions of oro_discriminants/3 group by
    *all* values, which is what a planner filters on; the two agree
    whenever an individual has at most one value per property.
  - Equivalent properties found best together (`hasColor`,
    `mainColorOfObject` and `dbp:color` in the OpenRobots ontology) are
    all listed, as oro-server 0.8.2 lists them: the values are inferred
    through each of them.
  - Literals are compared by value, as everywhere in oro (`12` equals
    `"12"^^xsd:integer`).  Blank nodes are never values.
  - Every list comes back in a stable order: classes and properties in
    the standard order of their IRIs, values in the order of their
    canonical keys, groups of differences types first.

Errors (ISO-shaped, mapped to ORO's exceptions by the server):

  | Formal                                           | when                          |
  |--------------------------------------------------|-------------------------------|
  | `existence_error(concept, IRI)`                  | a resource unknown in the model |
  | `domain_error(oro_comparable, kinds(KA, KB))`    | an instance compared with a class (KA, KB among `instance`, `class`, `object_property`, `datatype_property`, `annotation_property`, `undecided`) |
  | `domain_error(oro_comparable, not_individuals)`  | two resources of the same kind that are not individuals, or a non-individual to discriminate |
  | `existence_error(agent, Model)`                  | an unknown model               |
*/

:- rdf_meta
    oro_similarities(+, r, r, -),
    oro_differences(+, r, r, -),
    oro_common_ancestors(+, r, r, -),
    oro_discriminate(+, t, -, -),
    oro_discriminants(+, t, -),
    oro_partition(+, t, r, -),
    excluded_predicate(r).

		 /*******************************
		 *     SIMILARITIES, DIFFERENCES *
		 *******************************/

%!  oro_similarities(+Model, +A, +B, -Similarities) is det.
%
%   Similarities is what the individuals A and B have in common in
%   Model (ORO-SPEC §10.3): `similar(rdf:type, Class)` for each of
%   their most specific common classes (oro_common_ancestors/4), then
%   `similar(Property, Value)` for each value of a default-namespace
%   property that A and B share, over the properties B has (ORO's
%   comparison is asymmetric there).  Values are IRIs or rdf_db
%   literal terms (A's form when A and B write the same value
%   differently).
%
%   @error existence_error(concept, X) if A or B is unknown.
%   @error domain_error(oro_comparable, _) if A and B are not both
%          individuals.

oro_similarities(Model0, A0, B0, Similarities) :-
    comparable_pair(Model0, A0, B0, Model, A, B),
    ancestors(Model, A, B, _TypesA, _TypesB, _Same, Ancestors),
    rdf_equal(rdf:type, Type),
    findall(similar(Type, C), member(C, Ancestors), TypeSims),
    compared_properties(Model, A, B, Props),
    findall(similar(P, V),
            ( member(P-(ValsA-ValsB), Props),
              member(K-V, ValsA),
              memberchk(K-_, ValsB)
            ),
            PropSims),
    append(TypeSims, PropSims, Similarities).

%!  oro_differences(+Model, +A, +B, -Differences) is det.
%
%   Differences is what tells the individuals A and B apart in Model
%   (ORO-SPEC §10.4), as a list of groups, each a list of rdf(S, P, O)
%   triples about A then about B:
%
%     - unless A and B have the same classes, for each most specific
%       common class C that has sub-classes, the direct sub-classes of
%       C each one belongs to (C itself if none): one group
%       `[rdf(A, rdf:type, X)..., rdf(B, rdf:type, Y)...]` (equivalent
%       classes give the same group, once);
%     - for each default-namespace property of B on which A and B
%       differ, the values only A has and the values only B has: one
%       group `[rdf(A, P, V)..., rdf(B, P, W)...]`.
%
%   Differences is `[]` when nothing tells them apart.
%
%   @error existence_error(concept, X) if A or B is unknown.
%   @error domain_error(oro_comparable, _) if A and B are not both
%          individuals.

oro_differences(Model0, A0, B0, Differences) :-
    comparable_pair(Model0, A0, B0, Model, A, B),
    ancestors(Model, A, B, TypesA, TypesB, Same, Ancestors),
    (   Same == true
    ->  TypeGroups = []
    ;   findall(Group,
                ( member(C, Ancestors),
                  type_group(Model, A-TypesA, B-TypesB, C, Group)
                ),
                TypeGroups0),
        list_to_set(TypeGroups0, TypeGroups)  % equivalent ancestors: one group
    ),
    compared_properties(Model, A, B, Props),
    findall(Group,
            ( member(P-(ValsA-ValsB), Props),
              \+ same_keys(ValsA, ValsB),
              findall(rdf(A, P, V), ( member(K-V, ValsA),
                                      \+ memberchk(K-_, ValsB) ), GA),
              findall(rdf(B, P, W), ( member(K-W, ValsB),
                                      \+ memberchk(K-_, ValsA) ), GB),
              append(GA, GB, Group)
            ),
            PropGroups),
    append(TypeGroups, PropGroups, Differences).

%   type_group(+Model, +A-TypesA, +B-TypesB, +C, -Group) is semidet:
%   the group of §10.4 for the common ancestor C, if C has sub-classes.

type_group(Model, A-TypesA, B-TypesB, C, Group) :-
    direct_below(Model, C, TypesA, BelowA),
    direct_below(Model, C, TypesB, BelowB),
    (   BelowA \== []
    ->  true
    ;   BelowB \== []
    ->  true
    ;   has_subclass(Model, C)
    ),
    branch(BelowA, C, BranchA),
    branch(BelowB, C, BranchB),
    rdf_equal(rdf:type, Type),
    findall(rdf(A, Type, X), member(X, BranchA), GA),
    findall(rdf(B, Type, Y), member(Y, BranchB), GB),
    append(GA, GB, Group).

branch(Below, C, Branch) :-
    (   Below == []
    ->  Branch = [C]
    ;   Branch = Below
    ).

same_keys(ValsA, ValsB) :-
    pairs_keys(ValsA, Keys),
    pairs_keys(ValsB, Keys).

%!  oro_common_ancestors(+Model, +A, +B, -Classes) is det.
%
%   Classes are the most specific named classes the individuals A and
%   B both belong to (ORO-SPEC §10.2): the direct classes of A when A
%   and B have exactly the same classes; `[owl:Thing]` when they share
%   nothing else; otherwise the common classes other than owl:Thing
%   with no common class strictly below them.
%
%   @error existence_error(concept, X) if A or B is unknown.
%   @error domain_error(oro_comparable, _) if A and B are not both
%          individuals.

oro_common_ancestors(Model0, A0, B0, Classes) :-
    comparable_pair(Model0, A0, B0, Model, A, B),
    ancestors(Model, A, B, _, _, _, Classes).

%   ancestors(+Model, +A, +B, -TypesA, -TypesB, -Same, -S2): the
%   named classes of A and B, whether they are the same (sameClass of
%   §10.1) and the common ancestors S2 of §10.2.

ancestors(Model, A, B, TypesA, TypesB, Same, S2) :-
    oro_classes_of(Model, A, TypesA),
    oro_classes_of(Model, B, TypesB),
    (   TypesA == TypesB
    ->  Same = true,
        oro_most_specific(Model, TypesA, S2)
    ;   Same = false,
        ord_intersection(TypesA, TypesB, S1),
        (   S1 = [_]
        ->  S2 = S1
        ;   rdf_equal(owl:'Thing', Thing),
            ord_del_element(S1, Thing, S1b),
            oro_most_specific(Model, S1b, S2)
        )
    ).

%   compared_properties(+Model, +A, +B, -Props): for each property of
%   the default namespace B has a value for, P-(ValsA-ValsB), the
%   values keyed by canonical value (ordered, one per key).

compared_properties(Model, A, B, Props) :-
    default_properties(Model, B, PropsB),
    default_properties(Model, A, PropsA),
    findall(P-(ValsA-ValsB),
            ( member(P-ValsB, PropsB),
              (   memberchk(P-ValsA0, PropsA)
              ->  ValsA = ValsA0
              ;   ValsA = []
              )
            ),
            Props).

default_properties(Model, X, Props) :-
    oro_default_namespace(NS),
    findall(P-(K-O),
            ( oro_holds(Model, X, P, O),
              sub_atom(P, 0, _, _, NS),
              \+ rdf_is_bnode(O),
              value_key(O, K)
            ),
            Triples),
    grouped_values(Triples, Props).

%   grouped_values(+Triples, -Props): P-(Key-Value) to P-KeyedValues,
%   ordered by P then Key, one Value per Key (the first seen).

grouped_values(Triples, Props) :-
    msort(Triples, Sorted),
    group_pairs_by_key(Sorted, Groups),
    maplist(unique_keys, Groups, Props).

unique_keys(P-Vals0, P-Vals) :-
    unique_keyed(Vals0, Vals).

unique_keyed([], []).
unique_keyed([K-V|T0], [K-V|T]) :-
    skip_key(T0, K, T1),
    unique_keyed(T1, T).

skip_key([K0-_|T0], K, T) :-
    K0 == K,
    !,
    skip_key(T0, K, T).
skip_key(T, _, T).

		 /*******************************
		 *         DISCRIMINATE         *
		 *******************************/

%!  oro_discriminate(+Model, +Individuals, -Total, -Best) is det.
%
%   Best are the properties that best tell Individuals (a list; order
%   and duplicates do not matter) apart in Model, and Total is Best if
%   each of them tells every individual from every other, else `[]`
%   (ORO-SPEC §10.5, made deterministic as the module documentation
%   says).  rdf:type stands for the set of direct classes.  Both lists
%   are ordered; they are `[]` when nothing tells Individuals apart.
%
%   @error existence_error(concept, X) for an unknown individual.
%   @error domain_error(oro_comparable, not_individuals) if one of
%          Individuals is not an individual.

oro_discriminate(Model, Individuals, Total, Best) :-
    discrimination(Model, Individuals, _, _, IsTotal, Best),
    (   IsTotal == true
    ->  Total = Best
    ;   Total = []
    ).

%!  oro_discriminants(+Model, +Individuals, -Discriminants) is det.
%
%   Discriminants are the best discriminants of oro_discriminate/4, in
%   the same order, each as `discriminant(Property, Partition)` where
%   Partition is oro_partition/4's: what a planner needs to ask "which
%   Property?" and keep the candidates the answer designates.  When
%   oro_discriminate/4 says they are total, every block of each
%   Partition is a single individual with a value.
%
%   @error as oro_discriminate/4.

oro_discriminants(Model0, Individuals, Discriminants) :-
    discrimination(Model0, Individuals, Model, Xs, _, Best),
    maplist(discriminant(Model, Xs), Best, Discriminants).

discriminant(Model, Xs, P, discriminant(P, Partition)) :-
    partition_of(Model, Xs, P, Partition).

%!  oro_partition(+Model, +Individuals, +Property, -Partition) is det.
%
%   Partition groups Individuals (a list; order and duplicates do not
%   matter) by all their values of Property in Model, asserted or
%   inferred (for rdf:type: their direct classes).  It is an ordered
%   list of Values-Members pairs: Values the ordered list of the values
%   (IRIs or rdf_db literal terms) some individuals have, Members the
%   ordered list of these individuals; `[]-Members` holds the
%   individuals without a value.  Literals compare by value.
%
%   @error as oro_discriminate/4.

oro_partition(Model0, Individuals, Property0, Partition) :-
    individual_set(Model0, Individuals, Model, Xs),
    must_be(nonvar, Property0),
    oro_resource(Property0, Property),
    partition_of(Model, Xs, Property, Partition).

partition_of(Model, Xs, P, Partition) :-
    findall(Sig-X, ( member(X, Xs),
                     property_signature(Model, X, P, Sig)
                   ), Pairs),
    partition_blocks(Pairs, Partition).

property_signature(Model, X, P, Sig) :-
    rdf_equal(rdf:type, P),
    !,
    type_signature(Model, X, Sig).
property_signature(Model, X, P, Sig) :-
    findall(K-O, ( oro_holds(Model, X, P, O),
                   \+ rdf_is_bnode(O),
                   value_key(O, K)
                 ), Vals0),
    msort(Vals0, Vals1),
    unique_keyed(Vals1, Sig).

%   partition_blocks(+SigMembers, -Partition): Sig-X pairs grouped by
%   the keys of Sig, as Values-Members.

partition_blocks(Pairs, Partition) :-
    findall(Keys-(X-Sig), ( member(Sig-X, Pairs),
                            pairs_keys(Sig, Keys)
                          ), Keyed0),
    msort(Keyed0, Keyed),
    group_pairs_by_key(Keyed, Groups),
    maplist(block, Groups, Partition).

block(_-[X-Sig|More], Values-[X|Xs]) :-
    pairs_values(Sig, Values),
    pairs_keys(More, Xs).

%   discrimination(+Model0, +Individuals, -Model, -Xs, -Total, -Best):
%   §10.5 over the ordered set Xs of Individuals.  A profile is X-Props,
%   Props the ordered P-Signature pairs of X after pruning, a Signature
%   an ordered list of Key-Value.

discrimination(Model0, Individuals, Model, Xs, Total, Best) :-
    individual_set(Model0, Individuals, Model, Xs),
    maplist(profile(Model), Xs, Profiles),
    length(Xs, N),
    property_stats(Profiles, Stats),
    include(selective, Stats, Candidates),
    (   Candidates == []
    ->  Total = false,
        Best = []
    ;   best_properties(Candidates, N, Total, Kept),
        prune_kept(Model, Profiles, Kept, Best)
    ).

%   profile(+Model, +X, -X-Props): steps 1 to 3.

profile(Model, X, X-Props) :-
    findall(P-O, oro_holds(Model, X, P, O), Facts),
    rdf_equal(rdf:type, Type),
    findall(C, member(Type-C, Facts), Types0),
    named_classes(Types0, Types),
    oro_most_specific(Model, Types, Direct),
    rdf_equal(owl:'Nothing', Nothing),
    findall(P-(K-O),
            ( member(P-O, Facts),
              \+ excluded_predicate(P),
              O \== Nothing,
              \+ rdf_is_bnode(O),
              value_key(O, K)
            ),
            Triples),
    grouped_values(Triples, Props0),
    prune_values(Model, Props0, Props1),
    findall(r(C)-C, member(C, Direct), TypeSig),
    ord_union(Props1, [Type-TypeSig], Props).

excluded_predicate(rdf:type).
excluded_predicate(owl:sameAs).
excluded_predicate(owl:differentFrom).
excluded_predicate(owl:topDataProperty).
excluded_predicate(owl:bottomDataProperty).
excluded_predicate(rdfs:label).
excluded_predicate(rdfs:comment).

%   type_signature(+Model, +X, -Sig): the direct classes of X, the
%   value set of rdf:type.

type_signature(Model, X, Sig) :-
    oro_direct_classes_of(Model, X, Classes),
    findall(r(C)-C, member(C, Classes), Sig).

%   named_classes(+Classes0, -Classes): ordered, without blank nodes,
%   owl:Nothing and owl:NamedIndividual (as oro_classes_of/3).

named_classes(Classes0, Classes) :-
    rdf_equal(owl:'Nothing', Nothing),
    rdf_equal(owl:'NamedIndividual', Named),
    exclude(unnamed_class(Nothing, Named), Classes0, Classes1),
    sort(Classes1, Classes).

unnamed_class(_, _, C) :-
    rdf_is_bnode(C),
    !.
unnamed_class(Nothing, _, Nothing) :-
    !.
unnamed_class(_, Named, Named).

%   Step 2: a value carried by several properties of X is removed from
%   every property strictly above another one carrying it.

prune_values(Model, Props0, Props) :-
    findall(K-P, ( member(P-Vals, Props0), member(K-_, Vals) ), KPs0),
    msort(KPs0, KPs),
    group_pairs_by_key(KPs, ByValue),
    findall(P-K, ( member(K-Ps, ByValue),
                   Ps = [_, _|_],
                   member(P, Ps),
                   member(Q, Ps),
                   Q \== P,
                   strict_subproperty(Model, Q, P)
                 ), Drop0),
    sort(Drop0, Drop),
    maplist(drop_values(Drop), Props0, Props).

drop_values([], Prop, Prop) :-
    !.
drop_values(Drop, P-Vals0, P-Vals) :-
    exclude(dropped(Drop, P), Vals0, Vals).

dropped(Drop, P, K-_) :-
    ord_memberchk(P-K, Drop).

strict_subproperty(Model, Q, P) :-
    oro_subproperty(Model, Q, P),
    \+ oro_subproperty(Model, P, Q).

%   property_stats(+Profiles, -Stats): stat(P, Occ, Count) for every
%   property of any profile: Occ individuals have it, with Count
%   distinct non-empty value sets.

property_stats(Profiles, Stats) :-
    findall(P-Keys, ( member(_-Props, Profiles),
                      member(P-Sig, Props),
                      pairs_keys(Sig, Keys)
                    ), PKs0),
    msort(PKs0, PKs),
    group_pairs_by_key(PKs, Groups),
    maplist(stat, Groups, Stats).

stat(P-KeySets, stat(P, Occ, Count)) :-
    length(KeySets, Occ),
    sort(KeySets, Distinct0),
    ord_del_element(Distinct0, [], Distinct),
    length(Distinct, Count).

%   Step 5: drop properties that tell nobody apart.

selective(stat(_, Occ, Count)) :-
    Count > 0,
    \+ ( Count =< 1, Occ > 1 ).

%   Step 6.

best_properties(Stats, N, Total, Kept) :-
    maplist(stat_key, Stats, Keyed),
    max_member(MaxKey-_, Keyed),
    findall(S, member(MaxKey-S, Keyed), M),
    (   MaxKey =:= N
    ->  Total0 = true
    ;   Total0 = false
    ),
    (   M = [stat(P, _, Count)]
    ->  Kept = [P],
        (   Total0 == true,
            Count =:= N
        ->  Total = true
        ;   Total = false
        )
    ;   aggregate_max_count(M, Largest),
        (   Largest =< N
        ->  findall(P, member(stat(P, _, Largest), M), Kept)
        ;   findall(P, ( member(stat(P, _, C), M), C >= N ), Kept)
        ),
        (   Largest < N
        ->  Total = false
        ;   Total = Total0
        )
    ).

stat_key(S, Key-S) :-
    S = stat(_, Occ, Count),
    Key is min(Occ, Count).

aggregate_max_count(M, Largest) :-
    findall(C, member(stat(_, _, C), M), Cs),
    max_list(Cs, Largest).

%   Step 7: among several kept properties, drop the direct
%   super-properties of another kept one, when an individual has both.
%   Equivalent properties (each a super-property of the other) are not
%   strictly above one another: they all stay, as oro-server 0.8.2 lists
%   them (the properties through which the values are inferred, as
%   getDifferences shows them too).

prune_kept(_, _, [P], [P]) :-
    !.
prune_kept(Model, Profiles, Kept, Best) :-
    exclude(super_of_kept(Model, Profiles, Kept), Kept, Best).

super_of_kept(Model, Profiles, Kept, P) :-
    member(Q, Kept),
    Q \== P,
    direct_superproperty(Model, Q, P),
    member(_-Props, Profiles),
    memberchk(P-_, Props),
    memberchk(Q-_, Props),
    !.

direct_superproperty(Model, Q, P) :-
    strict_subproperty(Model, Q, P),
    \+ ( oro_subproperty(Model, Q, R),
         R \== P,
         R \== Q,
         strict_subproperty(Model, Q, R),
         strict_subproperty(Model, R, P)
       ).

		 /*******************************
		 *            INPUT             *
		 *******************************/

%   comparable_pair(+Model0, +A0, +B0, -Model, -A, -B): §10.1.

comparable_pair(Model0, A0, B0, Model, A, B) :-
    oro_resolve_model(Model0, Model),
    concept(Model, A0, A),
    concept(Model, B0, B),
    resource_kind(Model, A, KindA),
    resource_kind(Model, B, KindB),
    (   KindA \== KindB
    ->  domain_error(oro_comparable, kinds(KindA, KindB))
    ;   KindA \== instance
    ->  domain_error(oro_comparable, not_individuals)
    ;   true
    ).

%   individual_set(+Model0, +Individuals, -Model, -Xs): the ordered set
%   of the individuals, each known and an individual.

individual_set(Model0, Individuals, Model, Xs) :-
    oro_resolve_model(Model0, Model),
    must_be(list, Individuals),
    maplist(concept(Model), Individuals, Xs0),
    sort(Xs0, Xs),
    (   member(X, Xs),
        resource_kind(Model, X, Kind),
        Kind \== instance
    ->  domain_error(oro_comparable, not_individuals)
    ;   true
    ).

concept(Model, Term, IRI) :-
    must_be(nonvar, Term),
    oro_resource(Term, IRI),
    (   oro_exists(Model, IRI)
    ->  true
    ;   existence_error(concept, IRI)
    ).

%   resource_kind(+Model, +R, -Kind): classes first, as the taxonomy
%   questions do.

resource_kind(Model, R, Kind) :-
    (   oro_class(Model, R)
    ->  Kind = class
    ;   oro_individual(Model, R)
    ->  Kind = instance
    ;   oro_property(Model, R, PKind)
    ->  property_kind(PKind, Kind)
    ;   Kind = undecided
    ).

property_kind(object, object_property).
property_kind(datatype, datatype_property).
property_kind(annotation, annotation_property).
property_kind(other, undecided).

		 /*******************************
		 *           HELPERS            *
		 *******************************/

%   direct_below(+Model, +C, +Types, -Below): the direct sub-classes
%   of C among the classes Types of an individual (dsub(C) ∩ types(x)
%   of §10.4).  As Types holds every super-class of its members, a
%   class of Types strictly below C with no class of Types strictly
%   between is a direct sub-class of C.

direct_below(Model, C, Types, Below) :-
    include(strictly_below_class(Model, C), Types, Under),
    exclude(has_strict_super_in(Model, Under), Under, Below).

strictly_below_class(Model, C, T) :-
    oro_strictly_below(Model, T, C).

%   has_subclass(+Model, +C): C has a named strict sub-class.

has_subclass(Model, C) :-
    rdf_equal(owl:'Nothing', Nothing),
    oro_subclass(Model, S, C),
    S \== Nothing,
    \+ rdf_is_bnode(S),
    \+ oro_subclass(Model, C, S),
    !.

has_strict_super_in(Model, Classes, C) :-
    member(D, Classes),
    D \== C,
    oro_strictly_below(Model, C, D),
    !.

%   value_key(+Term, -Key): a canonical key under which equal values
%   compare equal: numbers by value, booleans by truth, strings by
%   text (language and xsd:string ignored).

value_key(literal(Value), Key) :-
    !,
    literal_key(Value, Key).
value_key(IRI, r(IRI)).

literal_key(type(Type, Lex), Key) :-
    !,
    (   oro_numeric_datatype(Type, _),
        catch(atom_number(Lex, N0), _, fail),
        number(N0)
    ->  normal_number(N0, N),
        Key = n(N)
    ;   rdf_equal(Type, xsd:boolean),
        boolean_lexical(Lex, B)
    ->  Key = b(B)
    ;   rdf_equal(Type, xsd:string)
    ->  text_atom(Lex, A),
        Key = s(A)
    ;   text_atom(Lex, A),
        Key = t(Type, A)
    ).
literal_key(lang(_, Lex), s(A)) :-
    !,
    text_atom(Lex, A).
literal_key(Lex, s(A)) :-
    text_atom(Lex, A).

normal_number(N0, N) :-
    (   float(N0),
        N0 =:= float_integer_part(N0),
        abs(N0) < 9.0e15
    ->  N is integer(N0)
    ;   N = N0
    ).

text_atom(Lex, A) :-
    (   atom(Lex)
    ->  A = Lex
    ;   format(atom(A), '~w', [Lex])
    ).

boolean_lexical(true, true).
boolean_lexical('1', true).
boolean_lexical(false, false).
boolean_lexical('0', false).
