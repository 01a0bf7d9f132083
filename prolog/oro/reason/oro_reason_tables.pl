:- module(oro_reason_tables,
          [ compile_schema/2,      % +Model, +Key
            retract_schema/1,      % +Key
            sub_class_of/3,        % +Key, ?Sub, ?Super
            sub_class_of/4,        % +Key, +Model, ?Sub, ?Super
            type_only_class/3,     % +Key, +Model, -Class
            class_key/3,           % +Key, +Model, +Class
            way/4,                 % +Key, +P, ?Q, ?Dir
            same/3,                % +Key, +X, -Y
            meta_class/1,          % ?Class
            oro_meta_namespace/1,  % +IRI
            oro_rdf_list/3,        % +Model, +List, -Members
            s_class/2,             % Key, Class
            s_sub/3,               % Key, Sub, Super (reflexive, transitive)
            s_prop/3,              % Key, Property, Kind
            s_subprop/3,           % Key, Sub, Super (reflexive, transitive)
            s_way/4,               % Key, P, Q, Dir: Q-edges imply P
            s_has_ways/2,          % Key, P
            s_trans_way/4,         % Key, P, T, Dir: T transitive
            s_transitive/2,        % Key, P
            s_functional/2,        % Key, P
            s_subj_implies/3,      % Key, Q, Class
            s_obj_implies/3,       % Key, Q, Class
            s_same/3,              % Key, X, Members
            s_has_same/1,          % Key
            s_char/3,              % Key, P, Characteristic
            s_disjoint/3,          % Key, C1, C2 (both ways)
            s_prop_disjoint/3,     % Key, P, Q (both ways)
            s_def/3,               % Key, Class, Definition
            s_chain/3,             % Key, P, Links
            s_hv_edge/4,           % Key, Q, Restriction, Value
            s_virtual/2,           % Key, Q: Q has virtual edges
            s_virtual_way/4,       % Key, P, Q, Dir: virtual Q-edges imply P
            s_entry/3,             % Key, Class, Condition
            s_entry_class/2,       % Key, Class
            s_entry_sub/3,         % Key, EntryClass, Super
            s_has_entries/1,       % Key
            s_implied/2            % Key, Class: typed by more than rdf:type
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(assoc)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_names)).

/** <module> Reasoning: the schema closure tables and their compilation

This module owns the schema closure tables of oro_reason, the dynamic
`s_*` predicates, each keyed by a schema key.  It alone writes them:
compile_schema/2 fills the tables of a fresh key from the schema of a
model and retract_schema/1 empties them.  It exports them for the
instance reasoning (oro_reason_holds) and the public predicates
(oro_reason) to read.  Which key is current for a model, and when an
old key may be emptied, is for oro_reason_schema to decide.

The compilation reads the class and property hierarchies, the property
characteristics, domains and ranges, owl:sameAs, the disjointness
axioms, and the OWL 2 RL class expressions and property chains (the
rule table is in oro_reason's documentation).  It turns them into
closures: each class with all its super-classes, each property with
the *ways* asserted edges imply it, the virtual edges of hasValue
restrictions and chains, and the *entries* (conditions that make an
individual an instance of a class expression).  The last section,
schema access, holds the small readers of the tables that the other
parts share (sub_class_of/3, way/4, same/3, ...).
*/

:- rdf_meta
    meta_class(r),
    facet(r, -).

%!  s_class(?Key, ?Class) is nondet.
%!  s_sub(?Key, ?Sub, ?Super) is nondet.
%!  s_prop(?Key, ?Property, ?Kind) is nondet.
%!  s_subprop(?Key, ?Sub, ?Super) is nondet.
%!  s_way(?Key, ?P, ?Q, ?Dir) is nondet.
%!  s_has_ways(?Key, ?P) is nondet.
%!  s_trans_way(?Key, ?P, ?T, ?Dir) is nondet.
%!  s_transitive(?Key, ?P) is nondet.
%!  s_functional(?Key, ?P) is nondet.
%!  s_subj_implies(?Key, ?Q, ?Class) is nondet.
%!  s_obj_implies(?Key, ?Q, ?Class) is nondet.
%!  s_same(?Key, ?X, ?Members) is nondet.
%!  s_has_same(?Key) is nondet.
%!  s_char(?Key, ?P, ?Characteristic) is nondet.
%!  s_disjoint(?Key, ?C1, ?C2) is nondet.
%!  s_prop_disjoint(?Key, ?P, ?Q) is nondet.
%!  s_def(?Key, ?Class, ?Definition) is nondet.
%!  s_chain(?Key, ?P, ?Links) is nondet.
%!  s_hv_edge(?Key, ?Q, ?Restriction, ?Value) is nondet.
%!  s_virtual(?Key, ?Q) is nondet.
%!  s_virtual_way(?Key, ?P, ?Q, ?Dir) is nondet.
%!  s_entry(?Key, ?Class, ?Condition) is nondet.
%!  s_entry_class(?Key, ?Class) is nondet.
%!  s_entry_sub(?Key, ?EntryClass, ?Super) is nondet.
%!  s_has_entries(?Key) is nondet.
%!  s_implied(?Key, ?Class) is nondet.
%
%   The schema closure tables, one set per schema key, filled by
%   compile_schema/2 and emptied by retract_schema/1 only: read them,
%   never write them, from the other parts.  The comment of each table
%   in the dynamic declaration below says what a row means.

:- dynamic
    s_class/2,                      % Key, Class
    s_sub/3,                        % Key, Sub, Super (reflexive, transitive)
    s_prop/3,                       % Key, Property, Kind
    s_subprop/3,                    % Key, Sub, Super (reflexive, transitive)
    s_way/4,                        % Key, P, Q, Dir: Q-edges imply P
    s_has_ways/2,                   % Key, P
    s_trans_way/4,                  % Key, P, T, Dir: T transitive
    s_transitive/2,                 % Key, P
    s_functional/2,                 % Key, P
    s_subj_implies/3,               % Key, Q, Class
    s_obj_implies/3,                % Key, Q, Class
    s_same/3,                       % Key, X, Members
    s_has_same/1,                   % Key
    s_char/3,                       % Key, P, Characteristic
    s_disjoint/3,                   % Key, C1, C2 (both ways)
    s_prop_disjoint/3,              % Key, P, Q (both ways)
    s_def/3,                        % Key, Class, Definition
    s_chain/3,                      % Key, P, Links
    s_hv_edge/4,                    % Key, Q, Restriction, Value
    s_virtual/2,                    % Key, Q: Q has virtual edges
    s_virtual_way/4,                % Key, P, Q, Dir: virtual Q-edges imply P
    s_entry/3,                      % Key, Class, Condition
    s_entry_class/2,                % Key, Class
    s_entry_sub/3,                  % Key, EntryClass, Super
    s_has_entries/1,                % Key
    s_implied/2.                    % Key, Class: typed by more than rdf:type

		 /*******************************
		 *         COMPILATION          *
		 *******************************/

%!  retract_schema(+Key) is det.
%
%   Empty the tables of Key.

retract_schema(Key) :-
    retractall(s_class(Key, _)),
    retractall(s_sub(Key, _, _)),
    retractall(s_prop(Key, _, _)),
    retractall(s_subprop(Key, _, _)),
    retractall(s_way(Key, _, _, _)),
    retractall(s_has_ways(Key, _)),
    retractall(s_trans_way(Key, _, _, _)),
    retractall(s_transitive(Key, _)),
    retractall(s_functional(Key, _)),
    retractall(s_subj_implies(Key, _, _)),
    retractall(s_obj_implies(Key, _, _)),
    retractall(s_same(Key, _, _)),
    retractall(s_has_same(Key)),
    retractall(s_char(Key, _, _)),
    retractall(s_disjoint(Key, _, _)),
    retractall(s_prop_disjoint(Key, _, _)),
    retractall(s_def(Key, _, _)),
    retractall(s_chain(Key, _, _)),
    retractall(s_hv_edge(Key, _, _, _)),
    retractall(s_virtual(Key, _)),
    retractall(s_virtual_way(Key, _, _, _)),
    retractall(s_entry(Key, _, _)),
    retractall(s_entry_class(Key, _)),
    retractall(s_entry_sub(Key, _, _)),
    retractall(s_has_entries(Key)),
    retractall(s_implied(Key, _)).

%!  compile_schema(+Model, +Key) is det.
%
%   Fill the tables of the fresh key Key with the closures of the
%   schema of Model, as the calling thread sees the store now.

compile_schema(Model, Key) :-
    findall(C-Def, class_definition(Model, C, Def), Defs0),
    sort(Defs0, Defs),
    compile_classes(Model, Key, Defs),
    compile_properties(Model, Key),
    compile_implications(Model, Key),
    compile_same_as(Model, Key),
    compile_axioms(Model, Key),
    compile_rl(Model, Key, Defs),
    compile_implied(Key).

schema_pairs(Model, P, Pairs) :-
    findall(S-O, oro_asserted(Model, S, P, O), Pairs0),
    sort(Pairs0, Pairs).

%   Classes and their reflexive-transitive super classes.  An
%   intersection is below each of its members and each member of a
%   union below the union.

compile_classes(Model, Key, Defs) :-
    rdf_equal(rdfs:subClassOf, SubClassOf),
    rdf_equal(owl:equivalentClass, Equivalent),
    schema_pairs(Model, SubClassOf, Subs),
    schema_pairs(Model, Equivalent, Eqs),
    findall(C, declared_class(Model, C), Declared),
    findall(C, ( member(D-Def, Defs),
                 (   C = D
                 ;   definition_class(Def, C)
                 )
               ), Defined),
    pairs_keys_values(Subs, SubKeys, SubValues),
    pairs_keys_values(Eqs, EqKeys, EqValues),
    append([Declared, Defined, SubKeys, SubValues, EqKeys, EqValues],
           Classes0),
    rdf_equal(owl:'Thing', Thing),
    sort([Thing|Classes0], Classes),
    findall(A-B, ( member(A-B, Subs)
                 ; member(A-B, Eqs)
                 ; member(B-A, Eqs)
                 ; member(A-intersection(Ms), Defs),
                   member(B, Ms)
                 ; member(B-union(Ms), Defs),
                   member(A, Ms)
                 ), Edges0),
    sort(Edges0, Edges),
    edges_graph(Classes, Edges, Graph),
    forall(member(C, Classes),
           ( assertz(s_class(Key, C)),
             reachable(Graph, C, Supers),
             forall(member(D, [C, Thing|Supers]),
                    assert_once(s_sub(Key, C, D)))
           )).

%   definition_class(+Definition, -Class): a class a definition names.

definition_class(intersection(Ms), C) :-
    member(C, Ms).
definition_class(union(Ms), C) :-
    member(C, Ms).
definition_class(some_values(_, class(C)), C).
definition_class(all_values(_, class(C)), C).

declared_class(Model, C) :-
    rdf_equal(rdf:type, Type),
    (   rdf_equal(owl:'Class', Meta)
    ;   rdf_equal(rdfs:'Class', Meta)
    ;   rdf_equal(owl:'Restriction', Meta)
    ),
    oro_asserted(Model, C, Type, Meta).
declared_class(Model, C) :-
    (   rdf_equal(rdfs:domain, P)
    ;   rdf_equal(rdfs:range, P)
    ),
    oro_asserted(Model, _, P, C),
    atom(C),
    \+ datatype(C).
declared_class(Model, C) :-
    (   rdf_equal(owl:disjointWith, P)
    ;   rdf_equal(owl:complementOf, P)
    ),
    (   oro_asserted(Model, C, P, _)
    ;   oro_asserted(Model, _, P, C)
    ).

datatype(C) :-
    rdf_equal(rdfs:'Literal', C),
    !.
datatype(C) :-
    rdf_equal(xsd:'', XSD),
    sub_atom(C, 0, _, _, XSD).

assert_once(Fact) :-
    (   call(Fact)
    ->  true
    ;   assertz(Fact)
    ).

%!  edges_graph(+Nodes, +Edges, -Graph) is det.
%!  reachable(+Graph, +Node, -Reached) is det.
%
%   Graph is an assoc from each node to its direct successors; Reached
%   is the ordered set of nodes reachable from Node in one or more steps
%   (Node itself only through a cycle, which equivalence creates).

edges_graph(Nodes, Edges, Graph) :-
    findall(N-[], member(N, Nodes), Empty),
    list_to_assoc(Empty, Graph0),
    foldl(add_edge, Edges, Graph0, Graph).

add_edge(A-B, G0, G) :-
    (   get_assoc(A, G0, Succ)
    ->  put_assoc(A, G0, [B|Succ], G)
    ;   put_assoc(A, G0, [B], G)
    ).

reachable(Graph, Node, Reached) :-
    successors(Graph, Node, Start),
    closure(Start, Graph, [], Reached).

closure([], _, Seen, Reached) :-
    sort(Seen, Reached).
closure([H|T], Graph, Seen, Reached) :-
    (   memberchk(H, Seen)
    ->  closure(T, Graph, Seen, Reached)
    ;   successors(Graph, H, Next),
        append(Next, T, Queue),
        closure(Queue, Graph, [H|Seen], Reached)
    ).

successors(Graph, Node, Succ) :-
    (   get_assoc(Node, Graph, Succ0)
    ->  Succ = Succ0
    ;   Succ = []
    ).

%   Properties: hierarchy, characteristics and the ways asserted edges
%   imply each property.

compile_properties(Model, Key) :-
    rdf_equal(rdfs:subPropertyOf, SubPropertyOf),
    rdf_equal(owl:equivalentProperty, Equivalent),
    rdf_equal(owl:inverseOf, InverseOf),
    schema_pairs(Model, SubPropertyOf, Subs),
    schema_pairs(Model, Equivalent, Eqs),
    schema_pairs(Model, InverseOf, Invs),
    findall(P-Kind, declared_property(Model, P, Kind), Declared),
    findall(P, ( member(P-_, Declared)
               ; member(P-_, Subs) ; member(_-P, Subs)
               ; member(P-_, Eqs) ; member(_-P, Eqs)
               ; member(P-_, Invs) ; member(_-P, Invs)
               ), Props0),
    sort(Props0, Props),
    findall(A-B, ( member(A-B, Subs)
                 ; member(A-B, Eqs)
                 ; member(B-A, Eqs)
                 ), SubEdges0),
    sort(SubEdges0, SubEdges),
    edges_graph(Props, SubEdges, SubGraph),
    forall(member(P, Props),
           ( reachable(SubGraph, P, Supers),
             forall(member(Q, [P|Supers]),
                    assert_once(s_subprop(Key, P, Q)))
           )),
    forall(member(P, Props),
           ( property_kind(Model, Key, P, Declared, Invs, Kind),
             assertz(s_prop(Key, P, Kind))
           )),
    forall(characteristic(Model, P, transitive),
           assert_once(s_transitive(Key, P))),
    forall(characteristic(Model, P, functional),
           assert_once(s_functional(Key, P))),
    findall(P, characteristic(Model, P, symmetric), Symmetric0),
    sort(Symmetric0, Symmetric),
    % ways: from (P, fwd), walk to sub-properties, inverses, symmetry
    findall(Super-Sub, member(Sub-Super, SubEdges), DownEdges),
    edges_graph(Props, DownEdges, DownGraph),
    findall(A-B, ( member(A-B, Invs) ; member(B-A, Invs) ), InvEdges),
    edges_graph(Props, InvEdges, InvGraph),
    forall(member(P, Props),
           ( ways(P, DownGraph, InvGraph, Symmetric, Ways),
             assertz(s_has_ways(Key, P)),
             forall(member(Q-Dir, Ways),
                    ( assertz(s_way(Key, P, Q, Dir)),
                      (   s_transitive(Key, Q)
                      ->  assertz(s_trans_way(Key, P, Q, Dir))
                      ;   true
                      )
                    ))
           )).

declared_property(Model, P, Kind) :-
    rdf_equal(rdf:type, Type),
    property_class(Class, Kind),
    oro_asserted(Model, P, Type, Class).
declared_property(Model, P, other) :-
    (   rdf_equal(rdfs:domain, D)
    ;   rdf_equal(rdfs:range, D)
    ),
    oro_asserted(Model, P, D, _).

:- rdf_meta property_class(r, -), characteristic_class(r, -).

property_class(owl:'ObjectProperty', object).
property_class(owl:'DatatypeProperty', datatype).
property_class(owl:'AnnotationProperty', annotation).
property_class(rdf:'Property', other).
property_class(owl:'TransitiveProperty', object).
property_class(owl:'SymmetricProperty', object).
property_class(owl:'FunctionalProperty', other).
property_class(owl:'InverseFunctionalProperty', object).
property_class(owl:'AsymmetricProperty', object).
property_class(owl:'IrreflexiveProperty', object).
property_class(owl:'ReflexiveProperty', object).

%   property_kind(+Model, +Key, +P, +Declared, +Inverses, -Kind): the
%   declared kind, else what the schema says: an inverse is an object
%   property, a sub-property has the kind of its super-properties, a
%   datatype range makes a datatype property and a class range an
%   object property.  What remains `other` is typed by its values at
%   query time (used_kind/4).

property_kind(Model, Key, P, Declared, Invs, Kind) :-
    (   declared_kind(P, Declared, Kind0)
    ->  Kind = Kind0
    ;   (   memberchk(P-_, Invs)
        ;   memberchk(_-P, Invs)
        )
    ->  Kind = object
    ;   s_subprop(Key, P, Q),
        Q \== P,
        declared_kind(Q, Declared, Kind0)
    ->  Kind = Kind0
    ;   rdf_equal(rdfs:range, Range),
        oro_asserted(Model, P, Range, R),
        atom(R)
    ->  (   datatype(R)
        ->  Kind = datatype
        ;   Kind = object
        )
    ;   Kind = other
    ).

declared_kind(P, Declared, Kind) :-
    (   memberchk(P-object, Declared)
    ->  Kind = object
    ;   memberchk(P-datatype, Declared)
    ->  Kind = datatype
    ;   memberchk(P-annotation, Declared)
    ->  Kind = annotation
    ).

characteristic(Model, P, Char) :-
    rdf_equal(rdf:type, Type),
    characteristic_class(Class, Char),
    oro_asserted(Model, P, Type, Class).

characteristic_class(owl:'TransitiveProperty', transitive).
characteristic_class(owl:'SymmetricProperty', symmetric).
characteristic_class(owl:'FunctionalProperty', functional).
characteristic_class(owl:'InverseFunctionalProperty', inverse_functional).
characteristic_class(owl:'AsymmetricProperty', asymmetric).
characteristic_class(owl:'IrreflexiveProperty', irreflexive).
characteristic_class(owl:'ReflexiveProperty', reflexive).

ways(P, DownGraph, InvGraph, Symmetric, Ways) :-
    way_closure([P-fwd], DownGraph, InvGraph, Symmetric, [], Ways).

way_closure([], _, _, _, Seen, Ways) :-
    sort(Seen, Ways).
way_closure([Q-D|T], Down, Inv, Sym, Seen, Ways) :-
    (   memberchk(Q-D, Seen)
    ->  way_closure(T, Down, Inv, Sym, Seen, Ways)
    ;   flip(D, F),
        successors(Down, Q, Subs),
        successors(Inv, Q, Invs),
        findall(S-D, member(S, Subs), Next1),
        findall(I-F, member(I, Invs), Next2),
        (   memberchk(Q, Sym)
        ->  Next3 = [Q-F]
        ;   Next3 = []
        ),
        append([Next1, Next2, Next3, T], Queue),
        way_closure(Queue, Down, Inv, Sym, [Q-D|Seen], Ways)
    ).

flip(fwd, bwd).
flip(bwd, fwd).

%   Domains and ranges: which asserted edges imply which types.

compile_implications(Model, Key) :-
    rdf_equal(rdfs:domain, Domain),
    rdf_equal(rdfs:range, Range),
    schema_pairs(Model, Domain, Domains),
    schema_pairs(Model, Range, Ranges),
    forall(( member(P-C, Domains),
             atom(C),
             way(Key, P, Q, Dir),
             sub_class_of(Key, C, Super)
           ),
           (   Dir == fwd
           ->  assert_once(s_subj_implies(Key, Q, Super))
           ;   assert_once(s_obj_implies(Key, Q, Super))
           )),
    forall(( member(P-C, Ranges),
             atom(C),
             \+ datatype(C),
             way(Key, P, Q, Dir),
             sub_class_of(Key, C, Super)
           ),
           (   Dir == fwd
           ->  assert_once(s_obj_implies(Key, Q, Super))
           ;   assert_once(s_subj_implies(Key, Q, Super))
           )).

%   s_implied(Key, C): C has instances other than those of its asserted
%   sub-classes, implied by a domain, a range or an entry class.  A
%   type check against any other class looks at the asserted types
%   alone.

compile_implied(Key) :-
    forall(( s_subj_implies(Key, _, C)
           ; s_obj_implies(Key, _, C)
           ; s_entry_sub(Key, _, C)
           ),
           assert_once(s_implied(Key, C))).

%   owl:sameAs equivalence classes.

compile_same_as(Model, Key) :-
    rdf_equal(owl:sameAs, SameAs),
    schema_pairs(Model, SameAs, Pairs),
    (   Pairs == []
    ->  true
    ;   assertz(s_has_same(Key)),
        findall(A-B, ( member(A-B, Pairs) ; member(B-A, Pairs) ), Edges),
        pairs_keys(Edges, Nodes0),
        sort(Nodes0, Nodes),
        edges_graph(Nodes, Edges, Graph),
        forall(member(N, Nodes),
               ( reachable(Graph, N, Reached),
                 ord_union([N], Reached, Members),
                 assertz(s_same(Key, N, Members))
               ))
    ).

%   The axioms the consistency checks need: property characteristics,
%   disjoint classes (owl:disjointWith, owl:complementOf,
%   owl:AllDisjointClasses) and disjoint properties
%   (owl:propertyDisjointWith, owl:AllDisjointProperties), both ways.

compile_axioms(Model, Key) :-
    forall(( characteristic(Model, P, Char),
             Char \== transitive,
             Char \== symmetric
           ),
           assert_once(s_char(Key, P, Char))),
    forall(declared_disjoint(Model, A, B),
           ( assert_once(s_disjoint(Key, A, B)),
             assert_once(s_disjoint(Key, B, A))
           )),
    forall(declared_disjoint_properties(Model, P, Q),
           ( assert_once(s_prop_disjoint(Key, P, Q)),
             assert_once(s_prop_disjoint(Key, Q, P))
           )).

declared_disjoint(Model, A, B) :-
    (   rdf_equal(owl:disjointWith, P)
    ;   rdf_equal(owl:complementOf, P)
    ),
    oro_asserted(Model, A, P, B).
declared_disjoint(Model, A, B) :-
    rdf_equal(owl:'AllDisjointClasses', All),
    all_members(Model, All, Classes),
    select(A, Classes, Others),
    member(B, Others).

declared_disjoint_properties(Model, P, Q) :-
    rdf_equal(owl:propertyDisjointWith, DP),
    oro_asserted(Model, P, DP, Q).
declared_disjoint_properties(Model, P, Q) :-
    rdf_equal(owl:'AllDisjointProperties', All),
    all_members(Model, All, Props),
    select(P, Props, Others),
    member(Q, Others).

all_members(Model, Class, Members) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:members, MembersP),
    oro_asserted(Model, Axiom, Type, Class),
    oro_asserted(Model, Axiom, MembersP, List),
    oro_rdf_list(Model, List, Members).

%!  oro_rdf_list(+Model, +List, -Members) is semidet.
%
%   Members are the elements of the well-formed RDF list List asserted
%   in Model (at most 10,000); fails on a malformed or cyclic list.

oro_rdf_list(Model, List, Members) :-
    rdf_equal(rdf:nil, Nil),
    rdf_equal(rdf:first, First),
    rdf_equal(rdf:rest, Rest),
    list_members(Model, List, Nil, First, Rest, Members, 10000).

list_members(_, Nil, Nil, _, _, [], _) :-
    !.
list_members(Model, Cell, Nil, First, Rest, [H|T], Budget) :-
    Budget > 0,
    oro_asserted(Model, Cell, First, H),
    oro_asserted(Model, Cell, Rest, Next),
    !,
    Budget1 is Budget - 1,
    list_members(Model, Next, Nil, First, Rest, T, Budget1).

		 /*******************************
		 *       CLASS EXPRESSIONS      *
		 *******************************/

%   class_definition(+Model, -Class, -Definition): a class expression
%   of the schema.

class_definition(Model, R, Def) :-
    rdf_equal(owl:onProperty, OnProperty),
    oro_asserted(Model, R, OnProperty, P),
    atom(P),
    \+ rdf_is_bnode(P),
    restriction(Model, R, P, Def).
class_definition(Model, C, Def) :-
    list_constructor(P, Functor),
    oro_asserted(Model, C, P, List),
    oro_rdf_list(Model, List, Members),
    Def =.. [Functor, Members].

:- rdf_meta
    list_constructor(r, -).

list_constructor(owl:intersectionOf, intersection).
list_constructor(owl:unionOf, union).
list_constructor(owl:oneOf, one_of).

restriction(Model, R, P, has_value(P, V)) :-
    rdf_equal(owl:hasValue, HasValue),
    oro_asserted(Model, R, HasValue, V).
restriction(Model, R, P, some_values(P, Filler)) :-
    rdf_equal(owl:someValuesFrom, Some),
    oro_asserted(Model, R, Some, F),
    filler(Model, F, Filler).
restriction(Model, R, P, all_values(P, Filler)) :-
    rdf_equal(owl:allValuesFrom, All),
    oro_asserted(Model, R, All, F),
    filler(Model, F, Filler).

%   filler(+Model, +Class, -Filler): `thing`, class(C) or
%   datatype(Datatype, Facets).

filler(Model, F, Filler) :-
    (   rdf_equal(F, owl:'Thing')
    ->  Filler = thing
    ;   atom(F),
        datatype(F)
    ->  Filler = datatype(F, [])
    ;   rdf_equal(owl:onDatatype, OnDatatype),
        oro_asserted(Model, F, OnDatatype, DT)
    ->  datatype_facets(Model, F, Facets),
        Filler = datatype(DT, Facets)
    ;   rdf_equal(rdf:type, Type),
        rdf_equal(rdfs:'Datatype', Datatype),
        oro_asserted(Model, F, Type, Datatype)
    ->  Filler = datatype(F, [unsupported])
    ;   Filler = class(F)
    ).

%   The facets of a datatype restriction: Name-Literal pairs of the
%   four range facets; any other facet is `unsupported` (it never
%   matches rather than matching too much).

datatype_facets(Model, F, Facets) :-
    rdf_equal(owl:withRestrictions, With),
    (   oro_asserted(Model, F, With, List),
        oro_rdf_list(Model, List, Items)
    ->  findall(Facet, ( member(Item, Items),
                         oro_asserted(Model, Item, P, V),
                         (   facet(P, Name)
                         ->  Facet = Name-V
                         ;   Facet = unsupported
                         )
                       ), Facets)
    ;   Facets = [unsupported]
    ).

facet(xsd:minInclusive, min_inclusive).
facet(xsd:maxInclusive, max_inclusive).
facet(xsd:minExclusive, min_exclusive).
facet(xsd:maxExclusive, max_exclusive).

chain_axiom(Model, P, Links) :-
    rdf_equal(owl:propertyChainAxiom, Chain),
    oro_asserted(Model, P, Chain, List),
    oro_rdf_list(Model, List, Members),
    Members \== [],
    maplist(chain_link(Model), Members, Links).

chain_link(Model, L, Link) :-
    (   rdf_is_bnode(L)
    ->  rdf_equal(owl:inverseOf, InverseOf),
        oro_asserted(Model, L, InverseOf, Q),
        atom(Q),
        Link = inverse(Q)
    ;   atom(L),
        Link = L
    ).

%   compile_rl(+Model, +Key, +Defs): the tables of class expressions
%   and chains.
%
%     - s_hv_edge(Key, Q, R, V): an instance of R has a virtual Q-edge
%       to V (cls-hv1); s_chain(Key, Q, Links): chains imply Q.
%     - s_virtual_way(Key, P, Q, Dir): virtual Q-edges imply P.
%     - s_entry(Key, D, Condition): a condition on an individual that
%       makes it an instance of D (cls-hv2, cls-svf1/2, cls-int1,
%       cls-oo, cls-avf, and domains and ranges of virtual edges);
%       s_entry_sub(Key, D, C): D is an entry class below C.
%
%   An entry is compiled only if its class matters: it is named, or is
%   used by another class expression or a disjointness axiom, or has
%   such a super-class.  `Bottle rdfs:subClassOf (hasShape value
%   cylinderShape)` makes every bottle have that shape, but does not
%   make everything of that shape an instance of the anonymous class.

compile_rl(Model, Key, Defs) :-
    forall(member(C-Def, Defs), assertz(s_def(Key, C, Def))),
    forall(chain_axiom(Model, P, Links), assertz(s_chain(Key, P, Links))),
    forall(member(R-has_value(Q, V), Defs),
           assertz(s_hv_edge(Key, Q, R, V))),
    findall(Q, ( s_hv_edge(Key, Q, _, _) ; s_chain(Key, Q, _) ), Vs0),
    sort(Vs0, Virtuals),
    forall(member(Q, Virtuals),
           ( assertz(s_virtual(Key, Q)),
             forall(implied_by(Key, Q, P, Dir),
                    assert_once(s_virtual_way(Key, P, Q, Dir)))
           )),
    findall(D-Cond, entry_condition(Model, Key, Defs, D, Cond), Entries0),
    sort(Entries0, Entries),
    relevant_classes(Key, Defs, Relevant),
    forall(( member(D-Cond, Entries),
             useful_entry(Key, Relevant, D)
           ),
           ( assertz(s_entry(Key, D, Cond)),
             assert_once(s_entry_class(Key, D)),
             assert_once(s_has_entries(Key)),
             forall(( entry_super(Key, D, C),
                      \+ redundant_entry(Key, Cond, C)
                    ),
                    assert_once(s_entry_sub(Key, D, C)))
           )).

%   An instance of an intersection is an instance of each member: for a
%   class C above one of the members, the intersection's entry finds
%   nothing the member does not (`Book rdfs:subClassOf (Artifact and
%   ...)` need not be tried for the instances of Artifact).

redundant_entry(Key, all_of(Ms), C) :-
    member(M, Ms),
    s_sub(Key, M, C),
    !.

%   implied_by(+Key, +Q, -P, -Dir): Q-edges imply P.

implied_by(Key, Q, P, Dir) :-
    (   s_has_ways(Key, Q)
    ->  s_way(Key, P, Q, Dir)
    ;   s_way(Key, P, Q, Dir)
    ;   P = Q,
        Dir = fwd
    ).

entry_super(Key, D, C) :-
    rdf_equal(owl:'Thing', Thing),
    (   s_sub(Key, D, C)
    *-> C \== Thing
    ;   C = D
    ).

entry_condition(_, _, Defs, D, value(Q, V)) :-
    member(D-has_value(Q, V), Defs).
entry_condition(_, _, Defs, D, some(Q, F)) :-
    member(D-some_values(Q, F), Defs).
entry_condition(_, _, Defs, D, all_of(Ms)) :-
    member(D-intersection(Ms0), Defs),
    Ms0 \== [],
    map_list_to_pairs(member_selectivity(Defs), Ms0, Keyed),
    keysort(Keyed, Sorted),
    pairs_values(Sorted, Ms).

entry_condition(_, _, Defs, D, one_of(Xs)) :-
    member(D-one_of(Xs), Defs).
entry_condition(_, _, Defs, C, avf(Q, R)) :-
    member(R-all_values(Q, class(C)), Defs).
entry_condition(Model, Key, _, C, Cond) :-
    rdf_equal(rdfs:domain, Domain),
    s_virtual(Key, Q),
    implied_by(Key, Q, P, Dir),
    oro_asserted(Model, P, Domain, C),
    atom(C),
    (   Dir == fwd
    ->  Cond = vsubj(Q)
    ;   Cond = vobj(Q)
    ).
entry_condition(Model, Key, _, C, Cond) :-
    rdf_equal(rdfs:range, Range),
    s_virtual(Key, Q),
    implied_by(Key, Q, P, Dir),
    oro_asserted(Model, P, Range, C),
    atom(C),
    \+ datatype(C),
    (   Dir == fwd
    ->  Cond = vobj(Q)
    ;   Cond = vsubj(Q)
    ).

%   member_selectivity(+Defs, +Class, -Rank): the instances of an
%   intersection are enumerated from its first member: a hasValue or
%   oneOf member has few, a named class may have many.

member_selectivity(Defs, C, Rank) :-
    (   memberchk(C-Def, Defs)
    ->  definition_rank(Def, Rank)
    ;   Rank = 5
    ).

definition_rank(has_value(_, _), 1).
definition_rank(one_of(_), 1).
definition_rank(some_values(_, class(_)), 3).
definition_rank(intersection(_), 4).
definition_rank(some_values(_, _), 6).
definition_rank(union(_), 6).
definition_rank(all_values(_, _), 7).

relevant_classes(Key, Defs, Relevant) :-
    findall(C, ( member(_-Def, Defs),
                 (   Def = intersection(Ms),
                     member(C, Ms)
                 ;   Def = some_values(_, class(C))
                 )
               ; member(C-all_values(_, _), Defs)
               ; s_disjoint(Key, C, _)
               ), Relevant0),
    sort(Relevant0, Relevant).

useful_entry(Key, Relevant, D) :-
    rdf_equal(owl:'Thing', Thing),
    s_sub(Key, D, S),
    S \== Thing,
    (   \+ rdf_is_bnode(S)
    ->  true
    ;   ord_memberchk(S, Relevant)
    ),
    !.

		 /*******************************
		 *        SCHEMA ACCESS         *
		 *******************************/

%!  sub_class_of(+Key, ?Sub, ?Super) is nondet.
%
%   Reflexive; a class unknown to the schema (only used as a type) is
%   its own class under owl:Thing.

sub_class_of(Key, Sub, Super) :-
    (   nonvar(Sub),
        \+ s_class(Key, Sub)
    ->  (   Super = Sub
        ;   \+ oro_meta_namespace(Sub),
            rdf_equal(owl:'Thing', Super)
        )
    ;   s_sub(Key, Sub, Super)
    ).

%!  sub_class_of(+Key, +Model, ?Sub, ?Super) is nondet.
%
%   sub_class_of/3, also enumerating, when Sub is unbound, the classes
%   only used as types, which s_sub/3 does not hold.

sub_class_of(Key, Model, Sub, Super) :-
    (   nonvar(Sub)
    ->  sub_class_of(Key, Sub, Super)
    ;   s_sub(Key, Sub, Super)
    ;   type_only_sub(Key, Model, Sub, Super)
    ).

%   type_only_sub(+Key, +Model, -Sub, ?Super): Sub is a class of Model
%   unknown to the schema, only used as the type of something, and
%   Super one of its super-classes: itself or owl:Thing.

type_only_sub(Key, Model, Sub, Super) :-
    (   nonvar(Super),
        \+ rdf_equal(owl:'Thing', Super)
    ->  \+ s_class(Key, Super),           % only itself is below it
        class_key(Key, Model, Super),
        Sub = Super
    ;   findall(C, type_only_class(Key, Model, C), Classes0),
        sort(Classes0, Classes),
        member(Sub, Classes),
        sub_class_of(Key, Sub, Super)
    ).

%!  type_only_class(+Key, +Model, -Class) is nondet.
%
%   Class is the type of something in Model and unknown to the schema
%   tables Key (once for each thing it types).

type_only_class(Key, Model, Class) :-
    rdf_equal(rdf:type, Type),
    oro_asserted(Model, _, Type, Class),
    \+ s_class(Key, Class),
    \+ meta_class(Class).

%!  way(+Key, +P, ?Q, ?Dir) is nondet.
%
%   Q-edges imply P, forward or backward (Dir `fwd` or `bwd`); a
%   property without ways of its own implies itself only.

way(Key, P, Q, Dir) :-
    (   s_has_ways(Key, P)
    ->  s_way(Key, P, Q, Dir)
    ;   Q = P,
        Dir = fwd
    ).

%!  same(+Key, +X, -Y) is multi.
%
%   Y is X or a member of its owl:sameAs class.

same(Key, X, Y) :-
    (   s_same(Key, X, Members)
    ->  member(Y, Members)
    ;   Y = X
    ).

%!  oro_meta_namespace(+IRI) is semidet.
%
%   IRI is in the rdf, rdfs, owl or xsd namespace.

oro_meta_namespace(IRI) :-
    atom(IRI),
    (   rdf_equal(rdf:'', NS)
    ;   rdf_equal(rdfs:'', NS)
    ;   rdf_equal(owl:'', NS)
    ;   rdf_equal(xsd:'', NS)
    ),
    sub_atom(IRI, 0, _, _, NS),
    !.

%!  class_key(+Key, +Model, +Class) is semidet.
%
%   Class is a class of Model: in the tables Key, or the type of
%   something that is not a meta class.

class_key(Key, Model, Class) :-
    (   s_class(Key, Class)
    ->  true
    ;   rdf_equal(rdf:type, Type),
        once(oro_asserted(Model, _, Type, Class)),
        \+ meta_class(Class)
    ).

%!  meta_class(?Class) is nondet.
%
%   Class is of the vocabulary of RDF and OWL (a schema class or an
%   axiom class), not a class of individuals.

meta_class(C) :-
    oro_schema_class(C).
meta_class(owl:'Ontology').
meta_class(owl:'AllDifferent').
meta_class(owl:'AllDisjointClasses').
meta_class(owl:'AllDisjointProperties').
meta_class(rdfs:'Datatype').
meta_class(rdf:'List').
meta_class(rdf:'Statement').
