:- module(oro_reason_holds,
          [ oro_holds/4,            % +Model, ?S, ?P, ?O
            oro_holds_normal/4,     % +Model, ?S, ?P, ?O
            oro_holds_keyed/5,      % +Key, +Model, ?S, ?P, ?O
            oro_holds_bag/6,        % +Model, ?Template, ?S, ?P, ?O, -Bag
            oro_datatype_member/2,  % +Literal, +Filler
            oro_literal_match/2,    % +Pattern, +Literal
            individual_key/3        % +Key, +Model, ?X
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/reason/oro_reason_tables)).
:- use_module(library(oro/reason/oro_reason_schema)).

/** <module> Reasoning: instance triples and types, derived when asked

The query-time half of oro_reason: whether a triple holds in the
inference closure of a model, and which ones do, derived from the
asserted triples with the schema tables (oro_reason_tables) of the
model.  A step follows the ways of a property, owl:sameAs, and the
virtual edges of hasValue restrictions and chains; transitive
properties are closed breadth first from a bound end; types come from
asserted types, the class hierarchy, domains, ranges and the entries
of class expressions.  Nested derivations carry their *ancestors*, the
goals in progress, so that cyclic class expressions end (see
oro_reason's documentation).  Literals match by value
(oro_literal_match/2, oro_datatype_member/2).

The answers of oro_holds/4 are found in a pinned region of the shared
tables (oro_reason_schema) and given one by one outside it.
*/

:- rdf_meta
    oro_holds(+, r, r, o),
    special_predicate(r),
    bare_type(r, -).

		 /*******************************
		 *          ANCESTORS           *
		 *******************************/

%   The goals in progress of a derivation: anc(Depth, Goals).  push/3
%   fails if Goal is a variant of one of them or if the derivation is
%   nested too deep.

max_depth(64).

push(Goal, anc(D, Goals), anc(D1, [Goal|Goals])) :-
    max_depth(Max),
    D < Max,
    \+ ( member(G, Goals), G =@= Goal ),
    D1 is D + 1.

		 /*******************************
		 *           HOLDS              *
		 *******************************/

%!  oro_holds(+Model, ?S, ?P, ?O) is nondet.
%
%   The triple S-P-O is in the inference closure of Model.  Each
%   distinct triple is returned once; with S, P and O bound it is
%   semidet.  Literal objects match by value (`12` matches
%   `"12"^^xsd:integer`; strings ignore language tags).  Model is a
%   model's name or alias (`default`, the robot id), as for oro_type/3,
%   oro_subclass/3, oro_subproperty/3, oro_class/2 and
%   oro_individual/2 (the others of this module take a model).
%
%   @error existence_error(agent, Model) for an unknown model.

oro_holds(Model0, S0, P0, O0) :-
    oro_resource(S0, S),
    oro_resource(P0, P),
    oro_object(O0, O),
    holds_pinned(Model0, S, P, O).

%!  oro_holds_normal(+Model, ?S, ?P, ?O) is nondet.
%
%   As oro_holds/4, for S, P and O already normal: IRIs, rdf_db literal
%   terms or variables, as oro_resource/2 and oro_object/2 give them and
%   as the store's triples hold them.  For callers that evaluate many
%   patterns whose terms are normal by construction (oro_solve/2 binds
%   the variables of its patterns to terms of the store), so that the
%   names are not normalised again at each step.

oro_holds_normal(Model, S, P, O) :-
    holds_pinned(Model, S, P, O).

%   holds_pinned(+Name, ?S, ?P, ?O): oro_holds_normal/4 for the model
%   Name names (a model or an alias), the answers found in a pinned
%   region of the shared tables, then given one by one out of it, so
%   that a caller that keeps choice points does not hold the pin.

holds_pinned(Name, S, P, O) :-
    (   ground(S-P-O)
    ->  pinned(model_holds_ground(Name, S, P, O))
    ;   pinned(model_derivations(Name, S-P-O, S, P, O, Triples0)),
        sort(Triples0, Triples),
        member(S-P-O, Triples)
    ).

%   model_holds_ground(+Name, +S, +P, +O) and model_derivations(+Name,
%   ?Template, ?S, ?P, ?O, -Bag): holds_ground/5 and derivations/7 with
%   the shared schema tables of the model Name names (model_schema/3),
%   as one goal for pinned/1 (a conjunction would be compiled at each
%   call).

model_holds_ground(Name, S, P, O) :-
    model_schema(Name, Model, Key),
    holds_ground(Key, Model, S, P, O).

model_derivations(Name, Template, S, P, O, Bag) :-
    model_schema(Name, Model, Key),
    derivations(Key, Model, Template, S, P, O, Bag).

%!  oro_holds_keyed(+Key, +Model, ?S, ?P, ?O) is nondet.
%
%   As oro_holds_normal/4, with the schema tables Key of Model, as
%   oro_with_shared_schema/3 gives them (and in its Goal, so that they
%   are not freed meanwhile).  For a caller that evaluates many
%   patterns in one go (a join), which finds the tables once.

oro_holds_keyed(Key, Model, S, P, O) :-
    (   ground(S-P-O)
    ->  holds_ground(Key, Model, S, P, O)
    ;   derivations(Key, Model, S-P-O, S, P, O, Triples0),
        sort(Triples0, Triples),
        member(S-P-O, Triples)
    ).

%!  oro_holds_bag(+Model, ?Template, ?S, ?P, ?O, -Bag) is det.
%
%   Bag is the list of the instantiations of Template, a term sharing
%   variables with S, P and O (normal, as for oro_holds_normal/4), for
%   the triples S-P-O in the inference closure of Model, *with
%   repetitions*: one per derivation, in no particular order.  The
%   solutions of oro_holds_normal/4 without their sorting: for a caller
%   that sorts what it keeps of them anyway (a find of one pattern).

oro_holds_bag(Model, Template, S, P, O, Bag) :-
    (   ground(S-P-O)
    ->  findall(Template, pinned(model_holds_ground(Model, S, P, O)), Bag)
    ;   pinned(model_derivations(Model, Template, S, P, O, Bag))
    ).

%   holds_ground(+Key, +Model, +S, +P, +O): a check.  A type check, the
%   most frequent in joins, goes to has_type/5 at once.

holds_ground(Key, Model, S, P, O) :-
    rdf_equal(rdf:type, Type),
    (   P == Type
    ->  has_type(Key, Model, anc(0, []), S, O)
    ;   holds(Key, Model, anc(0, []), S, P, O)
    ),
    !.

%   derivations(+Key, +Model, ?Template, ?S, ?P, ?O, -Bag): Template for
%   each derivation of S-P-O, but those whose predicate is a blank node.

derivations(Key, Model, Template, S, P, O, Bag) :-
    findall(Template,
            ( holds(Key, Model, anc(0, []), S, P, O),
              \+ rdf_is_bnode(P)
            ),
            Bag).

holds(Key, Model, Anc, S, P, O) :-
    var(P),
    !,
    candidate_predicate(Key, Model, S, O, P),
    holds(Key, Model, Anc, S, P, O).
holds(Key, Model, Anc, S, P, O) :-
    special_predicate(P),
    !,
    special_holds(P, Key, Model, Anc, S, O).
holds(Key, Model, Anc, S, P, O) :-
    step(Key, Model, Anc, P, S, O).
holds(Key, Model, Anc, S, P, O) :-
    s_trans_way(Key, P, T, Dir),
    (   Dir == fwd
    ->  transitive(Key, Model, Anc, T, S, O)
    ;   transitive(Key, Model, Anc, T, O, S)
    ).

special_predicate(rdf:type).
special_predicate(rdfs:subClassOf).
special_predicate(rdfs:subPropertyOf).
special_predicate(owl:sameAs).

special_holds(P, Key, Model, Anc, S, O) :-
    rdf_equal(P, rdf:type),
    !,
    type(Key, Model, Anc, S, O).
special_holds(P, Key, Model, _, S, O) :-
    rdf_equal(P, rdfs:subClassOf),
    !,
    (   nonvar(S)
    ->  class_key(Key, Model, S),
        sub_class_of(Key, S, O)
    ;   sub_class_of(Key, Model, S, O)
    ).
special_holds(P, Key, _Model, _, S, O) :-
    rdf_equal(P, rdfs:subPropertyOf),
    !,
    s_subprop(Key, S, O).
special_holds(_SameAs, Key, Model, _, S, O) :-
    (   nonvar(S)
    ->  same_as_known(Key, Model, S),
        same(Key, S, O)
    ;   nonvar(O)
    ->  same_as_known(Key, Model, O),
        same(Key, O, S)
    ;   s_same(Key, S, Members),
        member(O, Members)
    ).

same_as_known(Key, Model, X) :-
    (   s_same(Key, X, _)
    ->  true
    ;   individual_key(Key, Model, X)
    ).

%   One step: an asserted edge implying P, through its ways, with
%   owl:sameAs substitution; or a virtual edge (hasValue, chains).

step(Key, Model, _, P, S, O) :-
    way(Key, P, Q, Dir),
    (   Dir == fwd
    ->  asserted_same(Key, Model, S, Q, O)
    ;   asserted_same(Key, Model, O, Q, S)
    ).
step(Key, Model, Anc, P, S, O) :-
    s_virtual_way(Key, P, Q, Dir),
    (   Dir == fwd
    ->  virtual_edge(Key, Model, Anc, Q, S, O)
    ;   virtual_edge(Key, Model, Anc, Q, O, S)
    ).

asserted_same(Key, Model, S, Q, O) :-
    (   s_has_same(Key)
    ->  same_in(Key, S, S1),
        same_in(Key, O, O1),
        asserted_match(Model, S1, Q, O1),
        same_out(Key, S1, S),
        same_out(Key, O1, O)
    ;   asserted_match(Model, S, Q, O)
    ).

same_in(Key, X, Y) :-
    (   var(X)
    ->  true
    ;   same(Key, X, Y)
    ).

same_out(Key, Y, X) :-
    (   var(X)
    ->  same(Key, Y, X)
    ;   once(same(Key, Y, X))           % X bound meanwhile: `X p X`
    ).

%   virtual_edge(+Key, +Model, +Anc, +Q, ?S, ?O): S Q O is derived by
%   a hasValue restriction (S is an instance of it) or a chain.

virtual_edge(Key, Model, Anc, Q, S, O) :-
    s_hv_edge(Key, Q, R, V),
    value_match(Key, V, O),
    (   var(S)
    ->  type(Key, Model, Anc, S, R)
    ;   atom(S),
        once(has_type(Key, Model, Anc, S, R))
    ).
virtual_edge(Key, Model, Anc, Q, S, O) :-
    s_chain(Key, Q, Links),
    push(chain(Q, S, O), Anc, Anc1),
    chain_holds(Key, Model, Anc1, Links, S, O).

value_match(Key, V, O) :-
    (   V = literal(_)
    ->  (   var(O)
        ->  O = V
        ;   O = literal(_),
            oro_literal_match(O, V)
        )
    ;   var(O)
    ->  same(Key, V, O)
    ;   once(same(Key, V, O))
    ).

%   A chain is walked from its bound end; intermediate nodes are
%   deduplicated.

chain_holds(Key, Model, Anc, Links, S, O) :-
    (   var(S),
        nonvar(O)
    ->  reverse(Links, Reversed),
        maplist(invert_link, Reversed, Inverted),
        chain_walk(Inverted, Key, Model, Anc, O, S)
    ;   chain_walk(Links, Key, Model, Anc, S, O)
    ).

invert_link(inverse(P), P) :-
    !.
invert_link(P, inverse(P)).

chain_walk([Link], Key, Model, Anc, X, Y) :-
    !,
    link_holds(Link, Key, Model, Anc, X, Y).
chain_walk([Link|Links], Key, Model, Anc, X, Y) :-
    findall(X-Z, ( link_holds(Link, Key, Model, Anc, X, Z),
                   atom(Z)
                 ), Pairs0),
    sort(Pairs0, Pairs),
    member(X-Z, Pairs),
    chain_walk(Links, Key, Model, Anc, Z, Y).

link_holds(inverse(P), Key, Model, Anc, X, Y) :-
    !,
    holds(Key, Model, Anc, Y, P, X).
link_holds(P, Key, Model, Anc, X, Y) :-
    holds(Key, Model, Anc, X, P, Y).

%   asserted_match(+Model, ?S, +Q, ?O): an asserted triple, literal
%   objects compared by value.

asserted_match(Model, S, Q, O) :-
    (   nonvar(O),
        O = literal(_)
    ->  literal_asserted(Model, S, Q, O)
    ;   oro_asserted(Model, S, Q, O)
    ).

literal_asserted(Model, S, Q, Pattern) :-
    (   nonvar(S)
    ->  oro_asserted(Model, S, Q, Literal),
        oro_literal_match(Pattern, Literal)
    ;   literal_key(Pattern, string(Text))
    ->  atom_string(Lex, Text),
        rdf(S, Q, literal(exact(Lex), Value)),
        Literal = literal(Value),
        oro_literal_match(Pattern, Literal),
        once(oro_asserted(Model, S, Q, Literal))
    ;   oro_asserted(Model, S, Q, Literal),
        oro_literal_match(Pattern, Literal)
    ).

%!  oro_literal_match(+Pattern, +Literal) is semidet.
%
%   The two literals have the same value: numbers compare numerically
%   whatever their numeric datatype, booleans by truth value, and
%   strings by their text, ignoring language tags and xsd:string.

oro_literal_match(Pattern, Literal) :-
    literal_key(Pattern, K1),
    literal_key(Literal, K2),
    same_key(K1, K2).

same_key(number(X), number(Y)) :-
    !,
    X =:= Y.
same_key(K, K).

literal_key(literal(Value), Key) :-
    value_key(Value, Key).

value_key(type(Type, Lex), Key) :-
    !,
    (   bare_type(Type, Kind),
        typed_key(Kind, Lex, Key0)
    ->  Key = Key0
    ;   atom_string(Lex, String),
        (   rdf_equal(Type, xsd:string)
        ->  Key = string(String)
        ;   Key = typed(Type, String)
        )
    ).
value_key(lang(_, Lex), string(String)) :-
    !,
    atom_string(Lex, String).
value_key(Lex, string(String)) :-
    atom_string(Lex, String).

typed_key(number, Lex, number(N)) :-
    atom_number(Lex, N).
typed_key(boolean, Lex, boolean(B)) :-
    boolean_lexical(Lex, B).

boolean_lexical(true, true).
boolean_lexical('1', true).
boolean_lexical(false, false).
boolean_lexical('0', false).

bare_type(Type, number) :-
    oro_numeric_datatype(Type, _).
bare_type(xsd:boolean, boolean).

%!  oro_datatype_member(+Literal, +Filler) is semidet.
%
%   Literal is a value of Filler, a datatype(Datatype, Facets) filler
%   of oro_class_definition/3: any literal for rdfs:Literal, a number
%   for a numeric xsd datatype (within the range facets), a boolean for
%   xsd:boolean, a string for xsd:string.

oro_datatype_member(Literal, datatype(DT, Facets)) :-
    Literal = literal(_),
    literal_key(Literal, Key),
    datatype_key(DT, Key),
    \+ memberchk(unsupported, Facets),
    forall(member(Facet-Bound, Facets),
           facet_holds(Facet, Key, Bound)).

datatype_key(DT, _) :-
    rdf_equal(DT, rdfs:'Literal'),
    !.
datatype_key(DT, Key) :-
    (   bare_type(DT, Kind)
    ->  functor(Key, Kind, 1)
    ;   rdf_equal(DT, xsd:string)
    ->  Key = string(_)
    ;   Key = typed(DT, _)
    ).

facet_holds(Facet, number(X), Bound) :-
    literal_key(Bound, number(B)),
    facet_compare(Facet, X, B).

facet_compare(min_inclusive, X, B) :- X >= B.
facet_compare(max_inclusive, X, B) :- X =< B.
facet_compare(min_exclusive, X, B) :- X > B.
facet_compare(max_exclusive, X, B) :- X < B.

%   Transitive closure of the edges implying T, breadth first, from a
%   bound end.  With both ends unbound, from every subject of an edge.

transitive(Key, Model, Anc, T, S, O) :-
    (   nonvar(S)
    ->  reach(Key, Model, Anc, T, fwd, S, O)
    ;   nonvar(O)
    ->  reach(Key, Model, Anc, T, bwd, O, S)
    ;   findall(S0, step(Key, Model, Anc, T, S0, _), Starts0),
        sort(Starts0, Starts),
        member(S, Starts),
        reach(Key, Model, Anc, T, fwd, S, O)
    ).

reach(Key, Model, Anc, T, Dir, From, To) :-
    (   nonvar(To)
    ->  reach_set(Key, Model, Anc, T, Dir, [From], [], To, Reached),
        memberchk(To, Reached)
    ;   reach_set(Key, Model, Anc, T, Dir, [From], [], _, Reached),
        member(To, Reached)
    ).

%   reach_set(..., +Queue, +Seen, ?Goal, -Reached): stops early once
%   Goal (if bound) is reached.

reach_set(_, _, _, _, _, [], Seen, _, Seen) :- !.
reach_set(_, _, _, _, _, _, Seen, Goal, Seen) :-
    nonvar(Goal),
    memberchk(Goal, Seen),
    !.
reach_set(Key, Model, Anc, T, Dir, [X|Queue], Seen, Goal, Reached) :-
    findall(Y, ( next(Key, Model, Anc, T, Dir, X, Y),
                 Y \= literal(_),
                 \+ memberchk(Y, Seen)
               ), Next0),
    sort(Next0, Next),
    append(Seen, Next, Seen1),
    append(Queue, Next, Queue1),
    reach_set(Key, Model, Anc, T, Dir, Queue1, Seen1, Goal, Reached).

next(Key, Model, Anc, T, fwd, X, Y) :-
    step(Key, Model, Anc, T, X, Y).
next(Key, Model, Anc, T, bwd, X, Y) :-
    step(Key, Model, Anc, T, Y, X).

%   Predicates that may hold between S and O when P is unbound.

candidate_predicate(Key, Model, S, O, P) :-
    findall(P0, candidate_predicate_(Key, Model, S, O, P0), Ps0),
    sort(Ps0, Ps),
    member(P, Ps).

candidate_predicate_(Key, Model, S, O, P) :-
    (   nonvar(S)
    ->  same_in(Key, S, S1),
        oro_asserted(Model, S1, Q, _),
        used_as(Key, Q, fwd, P)
    ;   nonvar(O)
    ->  same_in(Key, O, O1),
        oro_asserted(Model, _, Q, O1),
        used_as(Key, Q, fwd, P)
    ;   oro_asserted(Model, _, Q, _),
        used_as(Key, Q, fwd, P)
    ).
candidate_predicate_(Key, Model, S, O, P) :-
    (   nonvar(S)
    ->  same_in(Key, S, S1),
        oro_asserted(Model, _, Q, S1)
    ;   nonvar(O)
    ->  same_in(Key, O, O1),
        oro_asserted(Model, O1, Q, _)
    ),
    used_as(Key, Q, bwd, P).
candidate_predicate_(Key, _, _, _, P) :-
    s_virtual_way(Key, P, _, _).
candidate_predicate_(_, _, _, _, P) :-
    special_predicate(P).

used_as(Key, Q, Dir, P) :-
    (   s_way(Key, P, Q, Dir)
    *-> true
    ;   Dir == fwd,
        P = Q
    ).

		 /*******************************
		 *            TYPES             *
		 *******************************/

type(Key, Model, Anc, X, C) :-
    (   nonvar(X)
    ->  (   nonvar(C)
        ->  has_type(Key, Model, Anc, X, C),
            !
        ;   types_of(Key, Model, Anc, X, Types),
            member(C, Types)
        )
    ;   nonvar(C)
    ->  instances_of(Key, Model, Anc, C, Instances),
        member(X, Instances)
    ;   findall(X0, individual_key(Key, Model, X0), Xs),
        member(X, Xs),
        types_of(Key, Model, Anc, X, Types),
        member(C, Types)
    ).

has_type(Key, Model, _, X, C) :-
    rdf_equal(owl:'Thing', C),
    !,
    same(Key, X, X1),
    individual_key(Key, Model, X1).
has_type(Key, Model, Anc, X, C) :-
    rdf_equal(rdf:type, Type),
    (   same(Key, X, X1),
        oro_asserted(Model, X1, Type, D),
        sub_class_of(Key, D, C)
    ;   s_implied(Key, C),
        implied_type(Key, Model, Anc, X, C)
    ).

implied_type(Key, Model, _, X, C) :-
    same(Key, X, X1),
    (   s_subj_implies(Key, Q, C),
        oro_asserted(Model, X1, Q, _)
    ;   s_obj_implies(Key, Q, C),
        oro_asserted(Model, _, Q, X1)
    ).
implied_type(Key, Model, Anc, X, C) :-
    s_entry_sub(Key, D, C),
    entry_member(Key, Model, Anc, X, D).

%   entry_member(+Key, +Model, +Anc, +X, +D): X meets a condition of
%   the entry class D.

entry_member(Key, Model, Anc, X, D) :-
    atom(X),
    push(type(X, D), Anc, Anc1),
    s_entry(Key, D, Cond),
    entry_holds(Cond, Key, Model, Anc1, X),
    !.

entry_holds(value(Q, V), Key, Model, Anc, X) :-
    holds(Key, Model, Anc, X, Q, V),
    !.
entry_holds(some(Q, Filler), Key, Model, Anc, X) :-
    holds(Key, Model, Anc, X, Q, Y),
    filler_member(Filler, Key, Model, Anc, Y),
    !.
entry_holds(all_of(Ms), Key, Model, Anc, X) :-
    forall(member(M, Ms),
           has_type(Key, Model, Anc, X, M)).
entry_holds(one_of(Xs), Key, _, _, X) :-
    same(Key, X, X1),
    memberchk(X1, Xs),
    !.
entry_holds(avf(Q, R), Key, Model, Anc, X) :-
    holds(Key, Model, Anc, Z, Q, X),
    atom(Z),
    has_type(Key, Model, Anc, Z, R),
    !.
entry_holds(vsubj(Q), Key, Model, Anc, X) :-
    virtual_edge(Key, Model, Anc, Q, X, _),
    !.
entry_holds(vobj(Q), Key, Model, Anc, X) :-
    virtual_edge(Key, Model, Anc, Q, _, X),
    !.

filler_member(thing, _, _, _, _).
filler_member(class(C), Key, Model, Anc, Y) :-
    atom(Y),
    has_type(Key, Model, Anc, Y, C),
    !.
filler_member(datatype(DT, Facets), _, _, _, Y) :-
    oro_datatype_member(Y, datatype(DT, Facets)).

types_of(Key, Model, Anc, X, Types) :-
    rdf_equal(rdf:type, Type),
    findall(C, ( same(Key, X, X1),
                 (   oro_asserted(Model, X1, Type, D),
                     sub_class_of(Key, D, C)
                 ;   oro_asserted(Model, X1, Q, _),
                     s_subj_implies(Key, Q, C)
                 ;   oro_asserted(Model, _, Q, X1),
                     s_obj_implies(Key, Q, C)
                 ;   individual_key(Key, Model, X1),
                     rdf_equal(owl:'Thing', C)
                 )
               ), Types0),
    sort(Types0, Base),
    (   s_has_entries(Key),
        atom(X)
    ->  findall(C, ( s_entry_class(Key, D),
                     \+ ord_memberchk(D, Base),
                     entry_member(Key, Model, Anc, X, D),
                     s_sub(Key, D, C)
                   ), Extra0),
        sort(Extra0, Extra),
        ord_union(Base, Extra, Types)
    ;   Types = Base
    ).

instances_of(Key, Model, _, C, Instances) :-
    rdf_equal(owl:'Thing', C),
    !,
    findall(X, individual_key(Key, Model, X), Instances).
instances_of(Key, Model, Anc, C, Instances) :-
    rdf_equal(rdf:type, Type),
    findall(X, ( (   s_sub(Key, D, C),
                     oro_asserted(Model, X1, Type, D)
                 ;   \+ s_class(Key, C),
                     oro_asserted(Model, X1, Type, C)
                 ;   s_subj_implies(Key, Q, C),
                     oro_asserted(Model, X1, Q, _)
                 ;   s_obj_implies(Key, Q, C),
                     oro_asserted(Model, _, Q, X1),
                     atom(X1)
                 ),
                 same(Key, X1, X)
               ), Instances0),
    sort(Instances0, Base),
    (   s_has_entries(Key),
        once(s_entry_sub(Key, _, C)),
        push(inst(C), Anc, Anc1)
    ->  findall(X, ( s_entry_sub(Key, D, C),
                     s_entry(Key, D, Cond),
                     entry_instance(Cond, Key, Model, Anc1, D, X)
                   ), Extra0),
        sort(Extra0, Extra),
        ord_union(Base, Extra, Instances)
    ;   Instances = Base
    ).

%   entry_instance(+Condition, +Key, +Model, +Anc, +D, -X): X is an
%   instance of the entry class D through Condition.

entry_instance(value(Q, V), Key, Model, Anc, _, X) :-
    holds(Key, Model, Anc, X, Q, V),
    atom(X).
entry_instance(some(Q, Filler), Key, Model, Anc, _, X) :-
    (   Filler = class(F)
    ->  type(Key, Model, Anc, Y, F),
        holds(Key, Model, Anc, X, Q, Y)
    ;   holds(Key, Model, Anc, X, Q, Y),
        filler_member(Filler, Key, Model, Anc, Y)
    ),
    atom(X).
entry_instance(all_of([M|_]), Key, Model, Anc, D, X) :-
    type(Key, Model, Anc, X, M),
    entry_member(Key, Model, Anc, X, D).
entry_instance(one_of(Xs), Key, _, _, _, X) :-
    member(X0, Xs),
    same(Key, X0, X).
entry_instance(avf(Q, R), Key, Model, Anc, _, X) :-
    type(Key, Model, Anc, Z, R),
    holds(Key, Model, Anc, Z, Q, X),
    atom(X).
entry_instance(vsubj(Q), Key, Model, Anc, _, X) :-
    virtual_edge(Key, Model, Anc, Q, X, _),
    atom(X).
entry_instance(vobj(Q), Key, Model, Anc, _, X) :-
    virtual_edge(Key, Model, Anc, Q, _, X),
    atom(X).

%!  individual_key(+Key, +Model, ?X) is nondet.
%
%   X is an individual of Model (with the schema tables Key): typed
%   with a non-meta class, or subject or object of an instance-level
%   triple.

individual_key(Key, Model, X) :-
    nonvar(X),
    !,
    same(Key, X, X1),
    individual_evidence(Model, X1),
    !.
individual_key(Key, Model, X) :-
    findall(X0, individual_candidate(Model, X0), Xs0),
    sort(Xs0, Xs1),
    include(is_individual(Model), Xs1, Xs2),
    findall(X1, ( member(X0, Xs2), same(Key, X0, X1) ), Xs3),
    sort(Xs3, Xs),
    member(X, Xs).

is_individual(Model, X) :-
    individual_evidence(Model, X),
    !.

%   individual_evidence(+Model, +X): X is typed by a class, or is the
%   subject or object of a property that is not of the vocabulary of
%   RDF or OWL; but the header of an ontology (`<iri> a owl:Ontology`)
%   is not an individual, whatever annotations it has.

individual_evidence(Model, X) :-
    \+ ontology_header(Model, X),
    evidence(Model, X).

evidence(Model, X) :-
    rdf_equal(rdf:type, Type),
    oro_asserted(Model, X, Type, C),
    \+ meta_class(C).
evidence(Model, X) :-
    oro_asserted(Model, X, Q, _),
    instance_predicate(Q).
evidence(Model, X) :-
    oro_asserted(Model, _, Q, X),
    instance_predicate(Q).

ontology_header(Model, X) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'Ontology', Ontology),
    oro_asserted(Model, X, Type, Ontology).

individual_candidate(Model, X) :-
    oro_asserted(Model, S, Q, O),
    (   rdf_equal(rdf:type, Q)
    ->  \+ meta_class(O),
        X = S
    ;   instance_predicate(Q)
    ->  (   X = S
        ;   atom(O),
            X = O
        )
    ).

instance_predicate(Q) :-
    (   \+ oro_meta_namespace(Q)
    ->  true
    ;   rdf_equal(Q, owl:sameAs)
    ;   rdf_equal(Q, owl:differentFrom)
    ).
