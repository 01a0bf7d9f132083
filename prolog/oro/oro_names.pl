:- module(oro_names,
          [ oro_default_namespace/1,    % -Namespace
            oro_prefix/2,               % ?Prefix, ?Namespace
            oro_name_iri/2,             % +Text, -IRI
            oro_iri_name/2,             % +IRI, -Text
            oro_local_name/2,           % +IRI, -Local
            oro_literal_lexical/2,      % +Literal, -Lexical
            oro_numeric_datatype/2,     % ?Type, ?Kind
            oro_term_text/2,            % +Term, -Text
            oro_term_local_text/2,      % +Term, -Text
            oro_term_light_text/2,      % +Term, -Text
            oro_resource/2,             % ?Term, -IRI
            oro_object/2,               % ?Term, -Object
            oro_rdf11/2,                % +Term, -Rdf11Term
            op(110, xfx, @),
            op(650, xfx, ^^)
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(semweb/rdf11), [rdf_lexical_form/2, rdf_canonical_literal/2]).

/** <module> Names: prefixes, expansion and contraction of ids

This module owns the namespaces oro knows.  Every prefix is registered
here, once, so `oro:'Fork'` works from the toplevel and from planners'
code (through rdf_meta/1), and every id crossing the protocol is
expanded or contracted here.

  - Expansion (text from a client to an IRI) follows ORO: a known prefix
    before the first `:` is replaced by its namespace; a name without
    `:` nor `#` is put in the default namespace `http://kb.openrobots.org#`;
    `<...>` brackets are accepted around any IRI.
  - Contraction (IRI to text for a client): the default namespace is
    dropped (`baboon`), other known namespaces become `prefix:local`
    (`owl:Thing`), anything else stays a full IRI; blank nodes become
    `anonymousNode_<id>`.

Expansion is on the path of every statement: a plain name costs one
scan and one atom_concat/3; names with a prefix or in brackets go
through a small cache owned by this module (name_expansion/2, bounded,
emptied when full; an expansion depends on the text only, so entries
never go stale).
*/

:- rdf_register_prefix(oro, 'http://kb.openrobots.org#').
:- rdf_register_prefix(cyc, 'http://sw.opencyc.org/concept/').
:- rdf_register_prefix(foaf, 'http://xmlns.com/foaf/0.1/').
:- rdf_register_prefix(dbo, 'https://dbpedia.org/ontology/').
:- rdf_register_prefix(dbp, 'https://dbpedia.org/property/').

%!  oro_default_namespace(-Namespace) is det.
%
%   The namespace of names given without a prefix.

oro_default_namespace('http://kb.openrobots.org#').

%!  oro_prefix(?Prefix, ?Namespace) is nondet.
%
%   The prefixes of the ORO protocol: the ones used in expansion and
%   contraction of names, in the order contraction tries them.

oro_prefix(rdf,  'http://www.w3.org/1999/02/22-rdf-syntax-ns#').
oro_prefix(rdfs, 'http://www.w3.org/2000/01/rdf-schema#').
oro_prefix(owl,  'http://www.w3.org/2002/07/owl#').
oro_prefix(xsd,  'http://www.w3.org/2001/XMLSchema#').
oro_prefix(oro,  'http://kb.openrobots.org#').
oro_prefix(cyc,  'http://sw.opencyc.org/concept/').
oro_prefix(foaf, 'http://xmlns.com/foaf/0.1/').
oro_prefix(dbo,  'https://dbpedia.org/ontology/').
oro_prefix(dbp,  'https://dbpedia.org/property/').

%!  oro_name_iri(+Text, -IRI) is det.
%
%   Expand a name as a client writes it (`Monkey`, `oro:Monkey`,
%   `rdf:type`, `<http://x.org/a#b>`, `http://x.org/a#b`) into an IRI.
%   Text is an atom or a string.

oro_name_iri(Text, IRI) :-
    must_be(text, Text),
    (   split_string(Text, ":#<", "", [_])      % a plain name: one scan
    ->  oro_default_namespace(NS),
        atom_concat(NS, Text, IRI)
    ;   (   string(Text)
        ;   atom(Text)
        )
    ->  cached_expansion(Text, IRI)
    ;   text_to_string(Text, String),           % a code or char list
        cached_expansion(String, IRI)
    ).

%   cached_expansion(+Text, -IRI): expand_name/2 through a cache.
%
%   Names with a prefix or in brackets are mostly vocabulary
%   (`rdf:type`, `owl:Thing`) and come back in every batch; expanding
%   one takes several scans, finding it in the cache (a dynamic
%   predicate, whose first argument SWI-Prolog indexes for strings and
%   atoms alike) about a twentieth of that.  The cache is owned by this
%   module and bounded: once it holds name_cache_size/1 names it is
%   emptied and refilled.  The expansion of a text depends on nothing
%   but the text (the prefixes are fixed), so an entry never goes
%   stale.

:- dynamic
    name_expansion/2.                   % Text, IRI

name_cache_size(4096).

cached_expansion(Text, IRI) :-
    (   name_expansion(Text, IRI0)
    ->  IRI = IRI0
    ;   expand_name(Text, IRI),
        remember_expansion(Text, IRI)
    ).

remember_expansion(Text, IRI) :-
    flag(oro_name_cache_entries, N, N+1),
    name_cache_size(Max),
    (   N >= Max
    ->  retractall(name_expansion(_, _)),
        flag(oro_name_cache_entries, _, 1)
    ;   true
    ),
    assertz(name_expansion(Text, IRI)).

%   expand_name(+Text, -IRI): Text is an atom or a string; every test
%   works on either, so no atom is made for the text itself.

expand_name(Text, IRI) :-
    (   string_code(1, Text, 0'<),
        string_length(Text, Len),
        string_code(Len, Text, 0'>)
    ->  sub_atom(Text, 1, _, 1, IRI)
    ;   sub_string(Text, Before, _, After, ":")  % the first colon
    ->  sub_atom(Text, 0, Before, _, Prefix),
        (   oro_prefix(Prefix, NS)
        ->  sub_atom(Text, _, After, 0, Local),
            atom_concat(NS, Local, IRI)
        ;   atom_string(IRI, Text)
        )
    ;   sub_string(Text, _, _, _, "#")
    ->  atom_string(IRI, Text)
    ;   oro_default_namespace(NS),
        atom_concat(NS, Text, IRI)
    ).

%!  oro_iri_name(+IRI, -Text) is det.
%
%   Contract an IRI for a client: `baboon`, `owl:Thing`, or the IRI
%   itself when no known namespace fits.  Blank nodes become
%   `anonymousNode_<id>`.

oro_iri_name(IRI, Text) :-
    rdf_is_bnode(IRI),
    !,
    atom_concat('_:', Id, IRI),
    atom_concat(anonymousNode_, Id, Text).
oro_iri_name(IRI, Text) :-
    oro_default_namespace(NS),
    atom_concat(NS, Local, IRI),
    Local \== '',
    !,
    Text = Local.
oro_iri_name(IRI, Text) :-
    oro_prefix(Prefix, NS),
    atom_concat(NS, Local, IRI),
    Local \== '',
    !,
    atomic_list_concat([Prefix, :, Local], Text).
oro_iri_name(IRI, IRI).

%!  oro_local_name(+IRI, -Local) is det.
%
%   The part of IRI after its last `#` (or, failing that, its last `/`);
%   the IRI itself when it has neither.

oro_local_name(IRI, Local) :-
    (   after_last(IRI, #, Local0)
    ->  Local = Local0
    ;   after_last(IRI, /, Local0)
    ->  Local = Local0
    ;   Local = IRI
    ).

%   after_last(+Atom, +Sep, -After): After is what follows the last
%   Sep (one character) in Atom.  sub_atom_icasechk/3 finds the first
%   Sep in C without leaving a choice point; IRIs have few separators.

after_last(Atom, Sep, After) :-
    sub_atom_icasechk(Atom, Before, Sep),
    Start is Before + 1,
    sub_atom(Atom, Start, _, 0, Rest),
    (   after_last(Rest, Sep, After0)
    ->  After = After0
    ;   After = Rest
    ).

%!  oro_literal_lexical(+Literal, -Lexical) is det.
%
%   The lexical form of an rdf_db literal term, as an atom, without
%   quotes, datatype or language tag.  A number of a numeric XSD
%   datatype (oro_numeric_datatype/2) is given in its canonical form:
%   `7` for `"+7"^^xsd:int`, `150.0` for `"150"^^xsd:double`, `48.5`
%   for `"48.50"^^xsd:decimal`.  rdf_db stores literals of some of
%   these datatypes that have the same value as one term, with the
%   lexical form of the first one asserted (`y v 7` after `x v "+7"^^xsd:int`
%   holds `"+7"`); the canonical form does not depend on that
%   history, and keeps a double a double for clients that read the
%   text back as a number.  A lexical form that is not a number (`INF`)
%   is left as it is.

oro_literal_lexical(literal(Value), Lexical) :-
    literal_value_lexical(Value, Lexical).

literal_value_lexical(type(Type, Lex), Lexical) :-
    !,
    (   canonical_number(Type, Lex, Canonical)
    ->  Lexical = Canonical
    ;   atomic_atom(Lex, Lexical)
    ).
literal_value_lexical(lang(_, Lex), Lexical) :-
    !,
    atomic_atom(Lex, Lexical).
literal_value_lexical(Lex, Lexical) :-
    atomic_atom(Lex, Lexical).

atomic_atom(Value, Atom) :-
    (   atom(Value)
    ->  Atom = Value
    ;   format(atom(Atom), '~w', [Value])
    ).

canonical_number(Type, Lex, Canonical) :-
    oro_numeric_datatype(Type, Kind),
    (   atom(Lex)
    ->  atom_number(Lex, N)
    ;   number(Lex)
    ->  N = Lex
    ),
    canonical_text(Kind, N, Canonical).

canonical_text(integer, N, Text) :-
    integer(N),
    atom_number(Text, N).
canonical_text(Kind, N, Text) :-
    Kind \== integer,
    F is float(N),
    F =:= F,                            % not NaN
    abs(F) =\= inf,
    format(atom(Text), '~w', [F]).

%!  oro_numeric_datatype(?Type, ?Kind) is nondet.
%
%   Type is a numeric XSD datatype (an IRI) of Kind: `integer` (and
%   the types derived from it), `decimal`, `float` or `double`.  The
%   one list of them: literals of these types compare by value, and
%   are written back in canonical form (oro_literal_lexical/2).

oro_numeric_datatype(Type, Kind) :-
    rdf_equal(xsd:'', XSD),
    (   atom(Type)
    ->  atom_concat(XSD, Local, Type),
        numeric_local(Local, Kind)
    ;   numeric_local(Local, Kind),
        atom_concat(XSD, Local, Type)
    ).

numeric_local(integer,            integer).
numeric_local(int,                integer).
numeric_local(long,               integer).
numeric_local(short,              integer).
numeric_local(byte,               integer).
numeric_local(nonNegativeInteger, integer).
numeric_local(positiveInteger,    integer).
numeric_local(negativeInteger,    integer).
numeric_local(nonPositiveInteger, integer).
numeric_local(unsignedLong,       integer).
numeric_local(unsignedInt,        integer).
numeric_local(unsignedShort,      integer).
numeric_local(unsignedByte,       integer).
numeric_local(decimal,            decimal).
numeric_local(float,              float).
numeric_local(double,             double).

%!  oro_term_text(+Term, -Text) is det.
%
%   The text of an RDF term in find, query and taxonomy results: a
%   contracted id for a resource, the bare lexical form for a literal.
%
%   @error instantiation_error if Term is a variable.

oro_term_text(Term, Text) :-
    (   var(Term)
    ->  instantiation_error(Term)
    ;   Term = literal(Value)
    ->  oro_literal_lexical(literal(Value), Text)
    ;   oro_iri_name(Term, Text)
    ).

%!  oro_term_local_text(+Term, -Text) is det.
%
%   The text of an RDF term in getInfos results: the local name of a
%   resource (`type`, `subClassOf`), the bare lexical form of a literal.

oro_term_local_text(literal(Value), Text) :-
    !,
    oro_literal_lexical(literal(Value), Text).
oro_term_local_text(IRI, Text) :-
    rdf_is_bnode(IRI),
    !,
    oro_iri_name(IRI, Text).
oro_term_local_text(IRI, Text) :-
    oro_local_name(IRI, Text).

%!  oro_term_light_text(+Term, -Text) is det.
%
%   ORO's "light" rendering of a term, used in statements sent back to
%   clients (`cow weight 150.7`): resources contracted; int, double,
%   boolean and plain literals as their lexical form; other typed
%   literals as `'lex'^^prefix:type`.

oro_term_light_text(literal(type(Type, Lex)), Text) :-
    \+ bare_datatype(Type),
    !,
    oro_iri_name(Type, TypeText),
    format(atom(Text), '\'~w\'^^~w', [Lex, TypeText]).
oro_term_light_text(Term, Text) :-
    oro_term_text(Term, Text).

bare_datatype(Type) :-
    rdf_equal(Type, xsd:int).
bare_datatype(Type) :-
    rdf_equal(Type, xsd:integer).
bare_datatype(Type) :-
    rdf_equal(Type, xsd:double).
bare_datatype(Type) :-
    rdf_equal(Type, xsd:boolean).

%!  oro_resource(?Term, -IRI) is det.
%
%   Normalise a resource given by a Prolog programmer: `fork1` (no
%   colon: the default namespace), `oro:'Fork'` (a registered prefix),
%   or a full IRI.  A variable is left alone.
%
%   @error type_error(oro_resource, Term) for anything else.

oro_resource(Var, IRI) :-
    var(Var),
    !,
    IRI = Var.
oro_resource(Prefix:Local, IRI) :-
    !,
    rdf_global_id(Prefix:Local, IRI).
oro_resource(Name, IRI) :-
    atom(Name),
    !,
    (   sub_atom_icasechk(Name, _, :)
    ->  IRI = Name
    ;   expand_name(Name, IRI)
    ).
oro_resource(Term, _) :-
    type_error(oro_resource, Term).

%!  oro_object(?Term, -Object) is det.
%
%   Normalise the object of a statement given by a Prolog programmer:
%   an rdf_db literal term, an rdf11 literal term (Value^^Type, Value
%   a lexical form as a string or atom, or a Prolog value: a number,
%   `true`, `false`, date(Y,M,D)...; Text@Lang), a number (xsd:int for
%   an integer, else xsd:double), a string (xsd:string), or a resource
%   as for oro_resource/2.  In a literal term, the datatype is named as a
%   resource (`xsd:integer` at run time too) and the lexical form and
%   language tag may be strings; a number as lexical form stands for
%   its text.  A literal term is ground: literals match by value.
%
%   @error instantiation_error for a literal term with a variable.
%   @error type_error(oro_literal, Term) for a literal term that is
%          none of literal(Lex), literal(type(Type, Lex)) and
%          literal(lang(Lang, Lex)).

oro_object(Var, Object) :-
    var(Var),
    !,
    Object = Var.
oro_object(literal(Value0), Object) :-
    !,
    (   literal_value(Value0, Value)
    ->  Object = literal(Value)
    ;   type_error(oro_literal, literal(Value0))
    ).
oro_object(Value^^Type0, literal(type(Type, Lex))) :-
    !,
    must_be(ground, Value^^Type0),
    oro_resource(Type0, Type),
    rdf11_lexical(Value, Type, Lex).
oro_object(Text@Lang0, literal(lang(Lang, Lex))) :-
    !,
    must_be(ground, Text@Lang0),
    must_be(text, Lang0),
    atom_string(Lang, Lang0),
    literal_lexical(Text, Lex).
oro_object(N, literal(type(Type, Lex))) :-
    number(N),
    !,
    (   integer(N)
    ->  rdf_equal(xsd:int, Type),
        atom_number(Lex, N)
    ;   rdf_equal(xsd:double, Type),
        (   float(N)
        ->  F = N
        ;   F is float(N)                   % a rational
        ),
        double_lexical(F, Lex)
    ).
oro_object(S, literal(type(Type, Lex))) :-
    string(S),
    !,
    rdf_equal(xsd:string, Type),
    atom_string(Lex, S).
oro_object(Term, IRI) :-
    oro_resource(Term, IRI).

%   rdf11_lexical(+Value, +Type, -Lex): the lexical form of the rdf11
%   literal Value^^Type.  Numbers are written as oro_object/2 writes
%   them; other Prolog values (booleans, dates...) as rdf11 does.

rdf11_lexical(Value, _, Lex) :-
    (   string(Value)
    ;   atom(Value),
        \+ memberchk(Value, [true, false])
    ),
    !,
    atom_string(Lex, Value).
rdf11_lexical(Value, _, Lex) :-
    integer(Value),
    !,
    atom_number(Lex, Value).
rdf11_lexical(Value, _, Lex) :-
    number(Value),
    !,
    F is float(Value),
    double_lexical(F, Lex).
rdf11_lexical(Value, Type, Lex) :-
    (   catch(rdf_lexical_form(Value^^Type, Text^^_), _, fail)
    ->  atom_string(Lex, Text)
    ;   type_error(oro_literal, Value^^Type)
    ).

%!  oro_rdf11(+Term, -Rdf11Term) is det.
%
%   Rdf11Term is Term with every rdf_db literal in it written as
%   library(semweb/rdf11) writes literals: Value^^Type with Value a
%   Prolog value where rdf11 has one (numbers, booleans, dates),
%   String^^Type otherwise, String@Lang, and String^^xsd:string for
%   a plain literal.  Lists, rdf(S,P,O) triples and any other
%   compound are converted argument by argument; IRIs are left alone.
%   The answers of oro_find/4, oro_holds/4... are rdf_db terms: this
%   gives them to code written for rdf11.

oro_rdf11(Term, Rdf11) :-
    (   var(Term)
    ->  Rdf11 = Term
    ;   Term = literal(Value)
    ->  rdf11_literal(Value, Rdf11)
    ;   compound(Term)
    ->  compound_name_arguments(Term, Name, Args0),
        maplist(oro_rdf11, Args0, Args),
        compound_name_arguments(Rdf11, Name, Args)
    ;   Rdf11 = Term
    ).

rdf11_literal(type(Type, Lex), Rdf11) :-
    !,
    atom_string(Lex, Text),
    (   catch(rdf_canonical_literal(Text^^Type, Canonical), _, fail)
    ->  Rdf11 = Canonical
    ;   Rdf11 = Text^^Type
    ).
rdf11_literal(lang(Lang, Lex), Text@Lang) :-
    !,
    atom_string(Lex, Text).
rdf11_literal(Lex, Text^^Type) :-
    atom_string(Lex, Text),
    rdf_equal(xsd:string, Type).

%   literal_value(+Value0, -Value): the value of an rdf_db literal term
%   with atoms where rdf_db wants them and the datatype an IRI; fails
%   for a value of no literal.

literal_value(Value, _) :-
    var(Value),
    !,
    instantiation_error(Value).
literal_value(type(Type0, Lex0), type(Type, Lex)) :-
    !,
    must_be(nonvar, Type0),
    oro_resource(Type0, Type),
    literal_lexical(Lex0, Lex).
literal_value(lang(Lang0, Lex0), lang(Lang, Lex)) :-
    !,
    must_be(text, Lang0),
    atom_string(Lang, Lang0),
    literal_lexical(Lex0, Lex).
literal_value(Lex0, Lex) :-
    (   atom(Lex0)
    ;   string(Lex0)
    ),
    literal_lexical(Lex0, Lex).

literal_lexical(Lex0, Lex) :-
    must_be(nonvar, Lex0),
    (   atom(Lex0)
    ->  Lex = Lex0
    ;   string(Lex0)
    ->  atom_string(Lex, Lex0)
    ;   number(Lex0)
    ->  atom_number(Lex, Lex0)
    ;   type_error(oro_literal, Lex0)
    ).

%   double_lexical(+Float, -Lex): the XSD lexical form of a double
%   (INF, -INF and NaN for the special values).

double_lexical(F, Lex) :-
    float_class(F, Class),
    (   Class == nan
    ->  Lex = 'NaN'
    ;   Class == infinite
    ->  (   F > 0
        ->  Lex = 'INF'
        ;   Lex = '-INF'
        )
    ;   atom_number(Lex, F)
    ).
