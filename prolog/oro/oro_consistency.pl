:- module(oro_consistency,
          [ oro_consistent/1,           % +Model
            oro_conflict/2,             % +Model, -Conflict
            oro_consistent_with/2,      % +Model, +Statements
            oro_safe_add/4              % +Model, +Statements, +Profile, -Accepted
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(oro_store).
:- use_module(oro_reason).
:- use_module(oro_parse).
:- use_module(oro_memory).

/** <module> Consistency: a robot must not believe a cow is a plant

A model is inconsistent when its inference closure contradicts an axiom
of its schema.  oro_conflict/2 finds the contradictions oro checks:

  - an individual in two disjoint classes (owl:disjointWith, either
    way, and the members of owl:AllDisjointClasses), or in a class and
    its owl:complementOf, or in owl:Nothing;
  - two different values of an owl:FunctionalProperty for one subject,
    or two different subjects with one value of an
    owl:InverseFunctionalProperty.  Literals differ when their values
    differ; individuals only when declared different (owl:differentFrom,
    owl:AllDifferent): OWL makes no unique-name assumption;
  - individuals both owl:sameAs and owl:differentFrom each other;
  - `x p x` for an owl:IrreflexiveProperty, `x p y` and `y p x` for an
    owl:AsymmetricProperty, and `x p y` with `x q y` for
    p owl:propertyDisjointWith q.

Types and values are those of the inference closure (oro_reason), so a
conflict through domains, ranges or sub-classes is found as well.
*/

:- rdf_meta
    disjoint_pair(+, r, r),
    characteristic(+, r, r).

%!  oro_consistent(+Model) is semidet.
%
%   Model has no conflict.

oro_consistent(Model0) :-
    oro_resolve_model(Model0, Model),
    \+ conflict(Model, _).

%!  oro_conflict(+Model, -Conflict) is nondet.
%
%   Conflict is a contradiction of Model: disjoint(X, C1, C2),
%   nothing(X), functional(P, X, V1, V2), inverse_functional(P, V, X1,
%   X2), same_and_different(X, Y), irreflexive(P, X), asymmetric(P, X,
%   Y) or disjoint_properties(P, Q, X, Y).

oro_conflict(Model0, Conflict) :-
    oro_resolve_model(Model0, Model),
    conflict(Model, Conflict).

conflict(Model, disjoint(X, C1, C2)) :-
    disjoint_pair(Model, C1, C2),
    oro_type(Model, X, C1),
    \+ rdf_is_bnode(X),
    oro_type(Model, X, C2).
conflict(Model, nothing(X)) :-
    oro_type(Model, X, owl:'Nothing'),
    \+ rdf_is_bnode(X).
conflict(Model, functional(P, X, V1, V2)) :-
    characteristic(Model, owl:'FunctionalProperty', P),
    findall(X-V, oro_holds(Model, X, P, V), Pairs),
    two_values(Pairs, X, V1, V2),
    different(Model, V1, V2).
conflict(Model, inverse_functional(P, V, X1, X2)) :-
    characteristic(Model, owl:'InverseFunctionalProperty', P),
    findall(V-X, oro_holds(Model, X, P, V), Pairs),
    two_values(Pairs, V, X1, X2),
    different(Model, X1, X2).
conflict(Model, same_and_different(X, Y)) :-
    declared_different(Model, X, Y),
    oro_same_individual(Model, X, Y).
conflict(Model, irreflexive(P, X)) :-
    characteristic(Model, owl:'IrreflexiveProperty', P),
    oro_holds(Model, X, P, X).
conflict(Model, asymmetric(P, X, Y)) :-
    characteristic(Model, owl:'AsymmetricProperty', P),
    oro_holds(Model, X, P, Y),
    oro_holds(Model, Y, P, X).
conflict(Model, disjoint_properties(P, Q, X, Y)) :-
    rdf_equal(owl:propertyDisjointWith, DP),
    oro_asserted(Model, P, DP, Q),
    oro_holds(Model, X, P, Y),
    oro_holds(Model, X, Q, Y).

%   disjoint_pair(+Model, -C1, -C2): the classes can share no instance.

disjoint_pair(Model, C1, C2) :-
    findall(A-B, declared_disjoint(Model, A, B), Pairs0),
    sort(Pairs0, Pairs),
    member(C1-C2, Pairs).

declared_disjoint(Model, A, B) :-
    (   rdf_equal(owl:disjointWith, P)
    ;   rdf_equal(owl:complementOf, P)
    ),
    oro_asserted(Model, A0, P, B0),
    (   A-B = A0-B0
    ;   A-B = B0-A0
    ).
declared_disjoint(Model, A, B) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'AllDisjointClasses', All),
    rdf_equal(owl:members, Members),
    oro_asserted(Model, Axiom, Type, All),
    oro_asserted(Model, Axiom, Members, List),
    rdf_list_members(Model, List, Classes),
    select(A, Classes, Others),
    member(B, Others).

characteristic(Model, Class, P) :-
    rdf_equal(rdf:type, Type),
    findall(P0, oro_asserted(Model, P0, Type, Class), Ps0),
    sort(Ps0, Ps),
    member(P, Ps).

%   two_values(+KeyValuePairs, -Key, -V1, -V2): two values of one key.

two_values(Pairs, Key, V1, V2) :-
    msort(Pairs, Sorted),
    append(_, [Key-V1|Rest], Sorted),
    member(Key-V2, Rest),
    V1 \== V2.

different(Model, V1, V2) :-
    (   V1 = literal(_), V2 = literal(_)
    ->  \+ oro_literal_match(V1, V2)
    ;   V1 = literal(_)
    ->  true
    ;   V2 = literal(_)
    ->  true
    ;   declared_different(Model, V1, V2)
    ).

%   declared_different(+Model, ?X, ?Y): X and Y (or individuals owl:sameAs
%   them) are declared different.

declared_different(Model, X, Y) :-
    rdf_equal(owl:differentFrom, DF),
    findall(A-B, ( oro_asserted(Model, A, DF, B)
                 ; all_different(Model, A, B)
                 ), Pairs0),
    sort(Pairs0, Pairs),
    (   nonvar(X), nonvar(Y)
    ->  oro_same_individual(Model, X, X1),
        oro_same_individual(Model, Y, Y1),
        (   memberchk(X1-Y1, Pairs)
        ;   memberchk(Y1-X1, Pairs)
        ),
        !
    ;   member(A-B, Pairs),
        (   X-Y = A-B
        ;   X-Y = B-A
        )
    ).

all_different(Model, A, B) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'AllDifferent', All),
    oro_asserted(Model, Axiom, Type, All),
    (   rdf_equal(owl:distinctMembers, P)
    ;   rdf_equal(owl:members, P)
    ),
    oro_asserted(Model, Axiom, P, List),
    rdf_list_members(Model, List, Members),
    append(_, [A|Rest], Members),
    member(B, Rest).

rdf_list_members(Model, List, Members) :-
    rdf_equal(rdf:nil, Nil),
    rdf_equal(rdf:first, First),
    rdf_equal(rdf:rest, Rest),
    list_members(Model, List, Nil, First, Rest, Members, 1000).

list_members(_, Nil, Nil, _, _, [], _) :- !.
list_members(Model, Cell, Nil, First, Rest, [H|T], Budget) :-
    Budget > 0,
    oro_asserted(Model, Cell, First, H),
    oro_asserted(Model, Cell, Rest, Next),
    !,
    Budget1 is Budget - 1,
    list_members(Model, Next, Nil, First, Rest, T, Budget1).
list_members(_, _, _, _, _, [], _).

%!  oro_consistent_with(+Model, +Statements) is semidet.
%
%   Model would be consistent with Statements added: they are added in
%   a transaction that is always rolled back, so nothing is kept and
%   nobody sees them.

oro_consistent_with(Model0, Statements) :-
    oro_resolve_model(Model0, Model),
    oro_statements(Statements, Triples, _),
    must_be(ground, Triples),
    catch(oro_store_write(check(Model),
                          ( oro_store_assert(Model, Triples, longterm),
                            (   \+ conflict(Model, _)
                            ->  throw(oro_hypothesis(true))
                            ;   throw(oro_hypothesis(false))
                            )
                          )),
          oro_hypothesis(Result),
          true),
    Result == true.

%!  oro_safe_add(+Model, +Statements, +Profile, -Accepted) is det.
%
%   Add Statements to Model keeping it consistent (ORO's safeAdd): if
%   the model is consistent with all of them they are all added and
%   Accepted is `true`; otherwise each statement is tried in turn and
%   kept only if the model stays consistent, and Accepted is `false`.
%   If Model is inconsistent already, nothing is added.  One
%   transaction.

oro_safe_add(Model0, Statements, Profile0, Accepted) :-
    oro_resolve_model(Model0, Model),
    oro_memory_profile(Profile0, Profile),
    oro_statements(Statements, Triples, _),
    (   member(T, Triples), \+ ground(T)
    ->  format(string(Text), "~w", [T]),
        throw(error(syntax_error(oro_statement_incomplete(Text)), _))
    ;   true
    ),
    oro_store_write(safe_add(Model),
                    safe_add(Model, Triples, Profile, Accepted)).

safe_add(Model, Triples, Profile, Accepted) :-
    (   conflict(Model, _)
    ->  Accepted = false
    ;   exclude(visible(Model), Triples, New),
        oro_store_assert(Model, Triples, Profile),
        (   \+ conflict(Model, _)
        ->  oro_memory_remember(Model, Profile, Triples),
            Accepted = true
        ;   oro_store_retract(Model, New),
            foldl(try_triple(Model, Profile), New, [], Kept),
            oro_memory_remember(Model, Profile, Kept),
            Accepted = false
        )
    ).

visible(Model, rdf(S, P, O)) :-
    once(oro_asserted(Model, S, P, O)).

try_triple(Model, Profile, Triple, Kept0, Kept) :-
    (   visible(Model, Triple)
    ->  Kept = Kept0
    ;   oro_store_assert(Model, [Triple], Profile),
        (   conflict(Model, _)
        ->  oro_store_retract(Model, [Triple]),
            Kept = Kept0
        ;   Kept = [Triple|Kept0]
        )
    ).
